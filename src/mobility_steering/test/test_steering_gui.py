#!/usr/bin/python3
"""Drives the real steering window with xdotool key presses and watches /cmd_vel."""
import os
import sys
import time
import unittest

import rospy
import rostest

from mobility_testing import images, x11
from mobility_testing.waiting import wait_for

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from twist_recorder import TwistRecorder  # noqa: E402

STOP_RED = (198, 40, 40)
RATE_HZ = 10.0
ZERO_REPEATS = 3
SHOT_DIR = os.environ.get('SCREENSHOT_DIR') or os.environ.get('ROS_HOME', '/tmp')


class SteeringGuiTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('steering_gui_test')
        cls.recorder = TwistRecorder('/cmd_vel')
        cls.window = x11.wait_window('^Robot Steering$', timeout_s=60)
        cls.recorder.wait_connected()

    def press(self, key):
        start = self.recorder.count()
        x11.key(self.window, key)
        return start

    def test_keys_rate_and_quiet_after_stop(self):
        start = self.recorder.count()
        time.sleep(1.0)  # observation window: nothing is published while at rest
        self.assertEqual(self.recorder.count(), start, 'published while at rest')

        mark = self.press('w')
        wait_for(lambda: self.recorder.seen(0.02, 0.0, mark), 10, 'linear.x 0.02 after W')
        mark = self.press('w')
        wait_for(lambda: self.recorder.seen(0.04, 0.0, mark), 10, 'linear.x 0.04 after W W')
        mark = self.press('a')
        wait_for(lambda: self.recorder.seen(0.04, 0.2, mark), 10, 'angular.z 0.2 after A')

        path = os.path.join(SHOT_DIR, 'steering_gui.png')
        shot = x11.screenshot_array(self.window, path)
        self.assertGreater(images.count_colour(shot, STOP_RED, 25), 5000,
                           f'no red STOP button in {path}')

        mark = self.recorder.count()
        wait_for(lambda: self.recorder.count() >= mark + 31, 10, '31 messages while moving')
        stamps = [t for t, _, _ in self.recorder.since(mark)][:31]
        intervals = [b - a for a, b in zip(stamps, stamps[1:])]
        rate_hz = (len(stamps) - 1) / (stamps[-1] - stamps[0])
        print(f'measured rate {rate_hz:.3f} Hz over {len(intervals)} intervals, '
              f'min {min(intervals):.3f} s max {max(intervals):.3f} s')
        self.assertAlmostEqual(rate_hz, RATE_HZ, delta=0.3)
        self.assertGreater(min(intervals), 0.05)
        self.assertLess(max(intervals), 0.2)

        mark = self.press('space')
        wait_for(lambda: self.recorder.seen(0.0, 0.0, mark), 10, 'a zero Twist after space')
        wait_for(lambda: self.recorder.quiet_for(1.5), 10, 'silence after the stop')
        after = self.recorder.since(mark)
        zeros = [r for r in after if r[1] == 0.0 and r[2] == 0.0]
        self.assertEqual(len(zeros), ZERO_REPEATS, f'zero messages after stop: {after}')
        self.assertEqual(after[-len(zeros):], zeros, 'last messages are the zeros')

    def test_stop_button_click(self):
        mark = self.press('s')
        wait_for(lambda: self.recorder.seen(-0.02, 0.0, mark), 10, 'linear.x -0.02 after S')
        shot = x11.screenshot_array(self.window, os.path.join(SHOT_DIR, 'steering_stop.png'))
        rows, cols = images.colour_mask(shot, STOP_RED, 25).nonzero()
        self.assertGreater(len(rows), 5000, 'no red STOP button to click')
        mark = self.recorder.count()
        x11.click(self.window, int(cols.mean()), int(rows.mean()))
        wait_for(lambda: self.recorder.seen(0.0, 0.0, mark), 10, 'a zero Twist after STOP')
        wait_for(lambda: self.recorder.quiet_for(1.5), 10, 'silence after STOP')


if __name__ == '__main__':
    rostest.rosrun('mobility_steering', 'steering_gui_keys', SteeringGuiTest, sys.argv)
