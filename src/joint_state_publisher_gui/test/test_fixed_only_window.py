#!/usr/bin/python3
"""A robot with fixed joints only: the window says so, empty joint states
are published at the default 10 Hz, and tf has the fixed link."""
import unittest

import rospy
import rostest
import tf2_ros

import gui_support as gs
from mobility_testing.waiting import wait_for


class FixedOnlyWindowTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_fixed_only_window')
        cls.report = rospy.get_param('~layout_report')
        cls.addClassCleanup(gs.remove_layout, cls.report)
        cls.states = gs.JointStateWatcher()
        cls.window = gs.open_window()

    def test_window_says_no_movable_joints(self):
        layout = gs.wait_layout(self.report, lambda l: l['message'] != '', 'the message')
        self.assertIn('no movable joints', layout['message'])
        self.assertEqual(layout['rows'], [])
        self.assertTrue(layout['title'].endswith('statue'))

    def test_empty_joint_states_at_ten_hz(self):
        first = wait_for(lambda: self.states.latest, gs.TIMEOUT_S, 'a joint_states message')
        self.assertEqual((list(first.name), list(first.position)), ([], []))
        start_count, start = self.states.count, rospy.get_time()
        wait_for(lambda: self.states.count >= start_count + 20, gs.TIMEOUT_S,
                 '20 more joint_states messages')
        rate_hz = (self.states.count - start_count) / (rospy.get_time() - start)
        self.assertAlmostEqual(rate_hz, 10.0, delta=1.5)

    def test_tf_has_fixed_link(self):
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        self.addCleanup(listener.unregister)

        def lookup():
            try:
                return buffer.lookup_transform('base_link', 'head_link', rospy.Time(0))
            except tf2_ros.TransformException:
                return None
        transform = wait_for(lookup, gs.TIMEOUT_S, 'tf base_link -> head_link')
        self.assertAlmostEqual(transform.transform.translation.z, 0.1)


if __name__ == '__main__':
    rostest.rosrun('joint_state_publisher_gui', 'fixed_only_window', FixedOnlyWindowTest)
