#!/usr/bin/python3
"""rate, zeros and source_list on the running node with the xqrobot."""
import math
import unittest

import rospy
import rostest
from sensor_msgs.msg import JointState

import gui_support as gs
from mobility_testing.waiting import wait_for

STEPS = 10000


class ParamsWindowTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_params_window')
        cls.report = rospy.get_param('~layout_report')
        cls.addClassCleanup(gs.remove_layout, cls.report)
        cls.states = gs.JointStateWatcher()
        cls.window = gs.open_window()

    def test_1_zeros_sets_start_position(self):
        positions = self.states.wait_positions(lambda p: len(p) == 4, 'joint_states')
        self.assertEqual(positions['right_wheel_joint'], 0.5)
        self.assertEqual(positions['left_wheel_joint'], 0.0)

    def test_2_rate_is_20_hz(self):
        wait_for(lambda: self.states.count > 0, gs.TIMEOUT_S, 'a joint_states message')
        start_count, start = self.states.count, rospy.get_time()
        wait_for(lambda: self.states.count >= start_count + 40, gs.TIMEOUT_S,
                 '40 more joint_states messages')
        rate_hz = (self.states.count - start_count) / (rospy.get_time() - start)
        self.assertAlmostEqual(rate_hz, 20.0, delta=2.5)

    def test_3_source_list_drives_joint_and_slider(self):
        pub = rospy.Publisher('/wheel_states', JointState, queue_size=1, latch=True)
        pub.publish(JointState(name=['left_wheel_joint'], position=[0.75]))
        self.states.wait_positions(lambda p: p['left_wheel_joint'] == 0.75,
                                   'left_wheel_joint = 0.75 from the source')
        expected_step = round((0.75 + math.pi) / (2.0 * math.pi) * STEPS)
        layout = gs.wait_layout(
            self.report, lambda l: gs.row(l, 'left_wheel_joint')['slider']['step'] ==
            expected_step, f'the left wheel slider at step {expected_step}')
        self.assertEqual(gs.row(layout, 'left_wheel_joint')['value_text'], '0.750 rad')


if __name__ == '__main__':
    rostest.rosrun('joint_state_publisher_gui', 'params_window', ParamsWindowTest)
