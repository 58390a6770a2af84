#!/usr/bin/python3
"""Launch files that open RViz, started without an X display: RViz says so once and the rest
runs headless. Without the wrapper RViz aborts (exit -6), and where it is `required` (the SLAM
and navigation launches) takes the whole launch down."""
import os
import queue
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import rospkg

from mobility_testing.ports import free_port
from test_navigation_launches import with_stand_ins

PACKAGE = rospkg.RosPack().get_path('turtlebot3_gazebo')
VIEW = os.path.join(PACKAGE, 'scripts', 'rviz_view')
MESSAGE = 'rviz: no X display'
TIMEOUT_S = 60


def headless_env(display=None, base=None):
    env = dict(base or os.environ, PATH='/usr/bin:/bin:' + os.environ['PATH'])
    env.pop('DISPLAY', None)
    if display is not None:
        env['DISPLAY'] = display
    return env


class Lines:
    """A process's merged output, line by line, read on a thread."""

    def __init__(self, process):
        self.process, self.lines, self.all = process, queue.Queue(), []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.process.stdout:
            self.all.append(line)
            self.lines.put(line)

    def wait_for(self, text):
        deadline = time.monotonic() + TIMEOUT_S
        while time.monotonic() < deadline:
            try:
                line = self.lines.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                break
            if text in line:
                return line
        raise AssertionError('no line with %r in %ds:\n%s' % (text, TIMEOUT_S, ''.join(self.all)))


class TestRvizView(unittest.TestCase):
    def check_waits(self, env):
        process = subprocess.Popen([VIEW, '-d', 'any.rviz'], env=env, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True)
        out = Lines(process)
        out.wait_for(MESSAGE)
        self.assertIsNone(process.poll(), 'exited: a required RViz would end the launch')
        process.send_signal(signal.SIGINT)  # as roslaunch stops it
        self.assertEqual(process.wait(timeout=10), 0)
        self.assertEqual(sum(MESSAGE in line for line in out.all), 1, out.all)

    def test_without_display_variable_it_says_so_and_waits(self):
        self.check_waits(headless_env())

    def test_with_a_display_nobody_serves_it_says_so_and_waits(self):
        self.check_waits(headless_env(display=':59999'))


class TestLaunchesHeadless(unittest.TestCase):
    def run_headless(self, launch, env, *args):
        """Starts the launch without a display, waits for the message and for the simulator's
        first /clock (long after RViz would have aborted), then stops it."""
        port = free_port()
        env = dict(env, ROS_MASTER_URI='http://localhost:%d' % port)
        process = subprocess.Popen(['roslaunch', '-p', str(port), 'turtlebot3_gazebo', launch]
                                   + list(args), env=env, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True,
                                   start_new_session=True)
        out = Lines(process)
        try:
            out.wait_for(MESSAGE)
            clock = subprocess.run(['rostopic', 'echo', '-n', '1', '/clock'], env=env,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   universal_newlines=True, timeout=TIMEOUT_S)
            self.assertEqual(clock.returncode, 0, clock.stdout)
            self.assertIsNone(process.poll(), ''.join(out.all))
        finally:
            os.killpg(process.pid, signal.SIGINT)
            process.wait(timeout=30)
        died = [line for line in out.all if 'has died' in line and '[rviz-' in line]
        self.assertEqual(died, [])
        return out.all

    def test_round_track_simulation(self):
        self.run_headless('roundTrack_simulation.launch', headless_env())

    def test_slam_launch_is_not_taken_down_by_its_required_rviz(self):
        with tempfile.TemporaryDirectory(prefix='nav_stand_ins_') as folder:
            env = headless_env(base=with_stand_ins(folder))
            lines = self.run_headless('roundTrack_slam.launch', env)
        self.assertFalse(any('shutting down' in line and 'required' in line for line in lines))


if __name__ == '__main__':
    unittest.main()
