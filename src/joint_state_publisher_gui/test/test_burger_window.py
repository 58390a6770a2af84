#!/usr/bin/python3
"""The Burger with the flag: sliders for both wheels and the flag; Randomize
(seeded) then Center, both clicked with xdotool."""
import math
import random
import unittest

import rospy
import rostest

import gui_support as gs
from mobility_testing import x11

JOINTS = ['wheel_left_joint', 'wheel_right_joint', 'flag_pole_joint']


class BurgerWindowTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_burger_window')
        cls.report = rospy.get_param('~layout_report')
        cls.addClassCleanup(gs.remove_layout, cls.report)
        cls.seed = rospy.get_param('~random_seed')
        cls.states = gs.JointStateWatcher()
        cls.window = gs.open_window()

    def test_sliders_randomize_and_center(self):
        layout = gs.wait_layout(self.report, lambda l: len(l['rows']) == 3, 'three slider rows')
        order = [r['name'] for r in layout['rows']]
        self.assertEqual(sorted(order), sorted(JOINTS))
        for entry in layout['rows']:
            self.assertEqual((entry['lower'], entry['upper']), (-math.pi, math.pi))
        self.states.wait_positions(lambda p: p == {n: 0.0 for n in JOINTS},
                                   'the three joints at 0')

        rng = random.Random(self.seed)
        expected = {name: rng.uniform(-math.pi, math.pi) for name in order}
        x11.click(self.window, *gs.centre(layout['widgets']['randomize']))
        positions = self.states.wait_positions(lambda p: p['flag_pole_joint'] != 0.0,
                                               'random positions after Randomize')
        for name in JOINTS:
            self.assertAlmostEqual(positions[name], expected[name], places=12)

        x11.click(self.window, *gs.centre(layout['widgets']['center']))
        self.states.wait_positions(lambda p: p == {n: 0.0 for n in JOINTS},
                                   'every joint back at 0 after Center')
        layout = gs.wait_layout(self.report,
                                lambda l: all(r['position'] == 0.0 for r in l['rows']),
                                'the rows showing 0')
        for entry in layout['rows']:
            self.assertEqual(entry['slider']['step'], entry['slider']['steps'] // 2)


if __name__ == '__main__':
    rostest.rosrun('joint_state_publisher_gui', 'burger_window', BurgerWindowTest)
