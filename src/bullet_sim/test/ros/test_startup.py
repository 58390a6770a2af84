#!/usr/bin/python3
"""bullet_sim_node's start: sim time begins with the first step, as a Gazebo world's time
begins when the world starts running. The wall time spent loading the world and
advertising the services is not caught up by a burst of steps faster than the real-time
factor (which would bring the first lidar scan, due at 0.2 s of sim time, earlier in wall
time than Gazebo gives it). Its warnings about the world name the world file once."""
import os
import re
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import rostest
from roslib.packages import find_node

MODELS = 1000  # a world that takes a noticeable time to read and build (about 0.5 s)
TOLERANCE_S = 0.05  # of sim time ahead of the wall time since the node said it was ready


def world_of_boxes(path, count):
    models = "".join(
        '<model name="box_%d"><static>true</static><pose>%d 5 0.5 0 0 0</pose>'
        '<link name="body"><collision name="c"><geometry><box><size>0.5 0.5 1</size></box>'
        '</geometry></collision></link></model>' % (i, i) for i in range(count))
    with open(path, "w") as out:
        out.write('<?xml version="1.0"?><sdf version="1.6"><world name="boxes">%s</world></sdf>'
                  % models)


def start_node(world, *params):
    node = find_node("bullet_sim", "bullet_sim_node")[0]
    return subprocess.Popen([node, "__name:=startup", "_world_file:=" + world] + list(params),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            bufsize=1)


def stop_node(process):
    process.send_signal(signal.SIGINT)
    process.wait(timeout=30)


class Startup(unittest.TestCase):
    def temp_folder(self):
        folder = tempfile.mkdtemp(prefix="bullet_sim_startup_")
        self.addCleanup(shutil.rmtree, folder, ignore_errors=True)
        return folder

    def test_sim_time_starts_with_the_first_step(self):
        world = os.path.join(self.temp_folder(), "boxes.world")
        world_of_boxes(world, MODELS)
        process = start_node(world, "_real_time_factor:=1", "_status_period:=0.05")
        ready, checked = None, 0
        try:
            deadline = time.monotonic() + 60
            for line in process.stdout:
                self.assertLess(time.monotonic(), deadline, "no status lines within 60 s")
                # rosconsole stamps each line with the wall time it was written at (no
                # /use_sim_time here); reading the pipe may come later.
                stamp = re.search(r"\[ INFO\] \[([\d.]+)\]", line)
                if not stamp:
                    continue
                if ready is None and "physics step" in line:  # the node's "world ..." line
                    ready = float(stamp.group(1))
                status = re.search(r"sim time ([\d.e+-]+) s", line)
                if ready is None or not status:
                    continue
                since_ready = float(stamp.group(1)) - ready
                self.assertLessEqual(float(status.group(1)), since_ready + TOLERANCE_S,
                                     "sim time ran ahead of the wall clock since the node was "
                                     "ready (%.3f s): %s" % (since_ready, line))
                checked += 1
                if since_ready > 0.6:
                    break
        finally:
            stop_node(process)
        self.assertIsNotNone(ready, "the node never said it was ready")
        self.assertGreater(checked, 2)

    def test_a_world_warning_names_the_file_once(self):
        # A saved <state> of a model the world does not have: the load goes on, with a
        # warning that names the file and the model.
        world = os.path.join(self.temp_folder(), "stale_state.world")
        with open(world, "w") as out:
            out.write('<?xml version="1.0"?><sdf version="1.6"><world name="stale">'
                      '<state world_name="stale"><model name="gone"><pose>1 2 0 0 0 0</pose>'
                      '</model></state></world></sdf>')
        process = start_node(world, "_real_time_factor:=1")
        warnings = []
        try:
            deadline = time.monotonic() + 60
            for line in process.stdout:
                self.assertLess(time.monotonic(), deadline, "the node was not ready in 60 s")
                if "WARN" in line:
                    warnings.append(line)
                if "physics step" in line:  # the node's "world ..." line: loaded
                    break
        finally:
            stop_node(process)
        stale = [line for line in warnings if '<model name="gone">' in line]
        self.assertEqual(len(stale), 1, "warnings: %r" % warnings)
        self.assertEqual(stale[0].count(world), 1, stale[0])


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "startup", Startup)
