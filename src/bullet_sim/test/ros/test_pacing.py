#!/usr/bin/python3
"""With ~real_time_factor 4 sim time (/clock) advances 4 times as fast as the wall clock,
and the node's status line reports the sim time, the factor and the robot's pose."""
import re
import threading
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock, Log

FACTOR = 4.0
WALL_WINDOW_S = 3.0


class Pacing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("pacing_test")

    def test_sim_time_runs_at_the_factor(self):
        lock = threading.Lock()
        latest = []

        def on_clock(msg):
            with lock:
                latest[:] = [msg.clock.to_sec()]

        sub = rospy.Subscriber("/clock", Clock, on_clock)
        deadline = time.monotonic() + 30
        while not latest or latest[0] < 1.0:
            self.assertLess(time.monotonic(), deadline, "/clock did not reach 1 s")
            time.sleep(0.01)
        with lock:
            sim_start, wall_start = latest[0], time.monotonic()
        time.sleep(WALL_WINDOW_S)  # the measured window of wall time
        with lock:
            sim_end, wall_end = latest[0], time.monotonic()
        sub.unregister()
        factor = (sim_end - sim_start) / (wall_end - wall_start)
        self.assertAlmostEqual(factor, FACTOR, delta=0.15 * FACTOR)

    def test_status_line(self):
        lines = []
        sub = rospy.Subscriber("/rosout", Log,
                               lambda m: lines.append(m.msg) if "real-time factor" in m.msg
                               and m.msg.startswith("sim time") else None)
        deadline = time.monotonic() + 30
        while len(lines) < 2:
            self.assertLess(time.monotonic(), deadline, "no status line on /rosout")
            time.sleep(0.01)
        sub.unregister()
        match = re.match(r"sim time ([\d.]+) s, real-time factor ([\d.]+), turtlebot3_burger "
                         r"at x (-?[\d.]+) y (-?[\d.]+) yaw (-?[\d.]+)", lines[-1])
        self.assertIsNotNone(match, lines[-1])
        self.assertAlmostEqual(float(match.group(2)), FACTOR, delta=0.2 * FACTOR)
        self.assertAlmostEqual(float(match.group(3)), 0.0, delta=0.05)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "pacing", Pacing)
