#!/usr/bin/python3
"""Without a simulator the Simulation panel says that none runs, shows no sim time or
factor, and its buttons are disabled."""
import os
import sys
import unittest

import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rviz_gui  # noqa: E402


class NoSimulator(unittest.TestCase):
    def test_panel_says_no_simulator_runs(self):
        rospy.init_node('rviz_no_simulator_check')
        panel = rviz_gui.Panel(rviz_gui.rviz_window(), rospy.get_param('~layout_report'))
        panel.wait_text('headline', lambda t: t.startswith('No simulator running'),
                        'the panel\'s no-simulator headline')
        report = panel.report()
        self.assertEqual(report['texts']['headline'],
                         'No simulator running (no /gazebo/pause_physics service)')
        self.assertEqual(report['texts']['sim_time'], '-')
        self.assertEqual(report['texts']['measured_rtf'], '-')
        for button in ('pause', 'play', 'step', 'reset_world', 'reset_simulation', 'set_rtf'):
            self.assertFalse(report['widgets'][button]['enabled'], button)


if __name__ == '__main__':
    rostest.rosrun('turtlebot3_gazebo', 'rviz_no_simulator', NoSimulator, sys.argv)
