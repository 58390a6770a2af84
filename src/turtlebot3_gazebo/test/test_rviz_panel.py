#!/usr/bin/python3
"""The Simulation panel and the Place robot tool in the round-track RViz window, clicked with
xdotool: pause stops /clock and play restarts it, Step N advances exactly N physics steps
(N ms), Reset world and Reset simulation put the robot back at its start, the panel lists the
simulator's models, the Target factor sets the pace, and a drag with the Place robot tool puts
the robot at the dragged pose (as get_model_state reports it)."""
import math
import os
import sys
import time
import unittest

import rospy
import rostest
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rviz_gui  # noqa: E402
from mobility_testing import x11  # noqa: E402
from mobility_testing.waiting import wait_for  # noqa: E402

STEP_S = 0.001
LANE = (-0.13, 1.8)            # a free spot in the west lane, north of the start line


def set_pose(x, y, yaw):
    rospy.wait_for_service('/gazebo/set_model_state', rviz_gui.TIMEOUT_S)
    state = ModelState(model_name=rviz_gui.ROBOT, reference_frame='world')
    state.pose.position.x, state.pose.position.y = x, y
    state.pose.orientation.z, state.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    res = rospy.ServiceProxy('/gazebo/set_model_state', SetModelState)(model_state=state)
    assert res.success, res.status_message


class RvizPanel(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('rviz_panel_check')
        cls.clock = rviz_gui.ClockWatcher()
        cls.window = rviz_gui.rviz_window()
        cls.panel = rviz_gui.Panel(cls.window, rospy.get_param('~layout_report'))
        cls.panel.wait_text('headline', lambda t: t == 'Simulation running',
                            'the panel to see the running simulation')
        # Where the robot started (the launch file's spawn pose): the resets go back there.
        cls.start = rviz_gui.model_pose()

    def assert_at(self, pose, expected, tol_m=0.01, tol_rad=0.02):
        self.assertLess(math.hypot(pose[0] - expected[0], pose[1] - expected[1]), tol_m,
                        f'robot at {pose}, expected {expected}')
        self.assertLess(abs(rviz_gui.angle_difference(pose[2], expected[2])), tol_rad,
                        f'robot heading {pose[2]}, expected {expected[2]}')

    def clock_span(self, wall_s):
        """How far /clock moves during wall_s seconds."""
        start = self.clock.now()
        time.sleep(wall_s)
        return self.clock.now() - start

    def pause(self):
        self.panel.click('pause')
        self.panel.wait_text('headline', lambda t: t == 'Simulation paused', 'paused')

    def test_1_pause_stops_clock_and_play_restarts_it(self):
        self.pause()
        self.assertEqual(self.clock_span(1.0), 0.0)
        self.panel.click('play')
        before = self.clock.now()
        self.clock.wait(lambda t: t > before + 0.5, 'the clock to run again after Play', 10)

    def test_2_step_advances_exactly_n_steps(self):
        self.pause()
        self.panel.type_into('step_count', '250')
        t0 = self.clock.now()
        self.panel.click('step')
        expected = t0 + 250 * STEP_S
        self.clock.wait(lambda t: t >= expected - 1e-9, f'/clock at {expected:.3f} s', 20)
        self.panel.wait_text('result', lambda t: t.startswith('stepped 250'), 'the step result')
        self.assertAlmostEqual(self.clock_span(0.5), 0.0)
        self.assertAlmostEqual(self.clock.now(), expected, places=6)
        self.panel.wait_text('headline', lambda t: t == 'Simulation paused', 'still paused')
        self.panel.screenshot(rospy.get_param('~panel_screenshot', ''))
        self.panel.click('play')

    def test_3_reset_world_puts_the_robot_back(self):
        set_pose(LANE[0], LANE[1], 0.0)
        self.assert_at(rviz_gui.model_pose(), (LANE[0], LANE[1], 0.0), tol_m=0.02, tol_rad=0.05)
        self.panel.click('reset_world')
        wait_for(lambda: math.hypot(rviz_gui.model_pose()[0] - self.start[0],
                                    rviz_gui.model_pose()[1] - self.start[1]) < 0.01,
                 10, 'the robot back at its start')
        self.assert_at(rviz_gui.model_pose(), self.start)

    def test_4_reset_simulation_restarts_time_and_robot(self):
        self.clock.wait(lambda t: t > 3.0, 'some sim time to reset')
        set_pose(LANE[0], LANE[1], 0.0)
        self.panel.click('reset_simulation')
        self.clock.wait(lambda t: t < 1.0, 'sim time back near 0', 10)
        self.assert_at(rviz_gui.model_pose(), self.start)

    def test_5_place_tool_drag_moves_the_robot(self):
        self.panel.type_into('model', rviz_gui.ROBOT)
        area, view = rviz_gui.view_area(self.window)
        press = tuple(int(round(v)) for v in view.project((LANE[0], LANE[1], 0.0), area))
        release = tuple(int(round(v)) for v in view.project((LANE[0] + 0.5, LANE[1] + 0.5, 0.0),
                                                            area))
        # Expected from the pixels actually used: PoseTool places at the pressed pixel's
        # ground point and heads towards the released one.
        p0, p1 = view.ground_point(press, area), view.ground_point(release, area)
        expected = (p0[0], p0[1], math.atan2(p1[1] - p0[1], p1[0] - p0[0]))
        wx, wy, _, _ = x11.geometry(self.window)
        centre = (area[0] + area[2] // 2 - wx, area[1] + area[3] // 2 - wy)
        x11.click(self.window, *centre)   # focus the 3D view (the Interact tool does nothing)
        x11.key(self.window, 'r')         # the Place robot tool's shortcut
        x11.drag(self.window, press[0] - wx, press[1] - wy, release[0] - wx, release[1] - wy)
        wait_for(lambda: math.hypot(rviz_gui.model_pose()[0] - expected[0],
                                    rviz_gui.model_pose()[1] - expected[1]) < 0.03,
                 10, f'the robot at the dragged place {expected}')
        self.assert_at(rviz_gui.model_pose(), expected, tol_m=0.03, tol_rad=0.03)

    def test_6_robot_chooser_lists_the_models(self):
        models = self.panel.wait_text('models', lambda t: rviz_gui.ROBOT in t.split(','),
                                      'the robot in the panel\'s chooser')
        self.assertIn(rviz_gui.ROBOT, models.split(','))

    def test_7_target_factor_sets_the_pace(self):
        self.panel.type_into('target_rtf', '2')
        self.panel.click('set_rtf')
        self.panel.wait_text('result', lambda t: 'real-time factor set to 2' in t,
                             'the factor to be set')
        time.sleep(1.0)
        self.assertAlmostEqual(self.clock_span(3.0) / 3.0, 2.0, delta=0.3)


if __name__ == '__main__':
    rostest.rosrun('turtlebot3_gazebo', 'rviz_panel', RvizPanel, sys.argv)
