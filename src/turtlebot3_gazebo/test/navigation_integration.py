#!/usr/bin/python3
"""AMCL and move_base on the round track (rostest node of navigation_integration.test).

1. AMCL, started 0.3 m and 0.3 rad off the Burger's true pose (the launch's
   initial_pose_x / initial_pose_a), converges to within 0.10 m and 0.1 rad while the robot
   turns in place.
2. move_base takes the Burger to 4 goals around the track, one per quarter, in sequence;
   each must succeed, and the robot's outline never touches a wall (true poses from the
   simulator against the world file's walls).
Figures (sim and wall times, errors, clearance) go to the JSON file of ~figures_file.
"""
import json
import math
import time
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseWithCovarianceStamped
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal

import sim_truth
from sim_truth import navigation_figures

CONVERGED_M, CONVERGED_RAD = 0.10, 0.1
GOALS = [(2.8, 1.72, 0.0), (4.6, 0.0, -math.pi / 2), (2.0, -2.14, math.pi),
         (-0.13, 0.3, math.pi / 2)]  # top, east, bottom and west lane: a quarter each
GOAL_TIMEOUT_SIM_S = 240.0
FIGURES = {}


def wait(condition, timeout_wall_s, what):
    end = time.monotonic() + timeout_wall_s
    while not condition():
        if time.monotonic() > end or rospy.is_shutdown():
            raise AssertionError('timed out waiting for ' + what)
        time.sleep(0.02)


class TestNavigation(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('navigation_integration')
        cls.truth = sim_truth.Truth()
        cls.driver = sim_truth.Driver()
        cls.estimates = []
        rospy.Subscriber('/amcl_pose', PoseWithCovarianceStamped, cls.on_estimate, queue_size=10)
        wait(lambda: cls.truth.get() is not None, 60, 'the true pose')
        wait(lambda: rospy.get_time() > 1.0, 60, 'sim time')

    @classmethod
    def on_estimate(cls, msg):
        p = msg.pose.pose
        estimate = (p.position.x, p.position.y, sim_truth.yaw_of(p.orientation))
        cls.estimates.append((msg.header.stamp.to_sec(),
                              navigation_figures.pose_error(estimate, cls.truth.get())))

    @classmethod
    def tearDownClass(cls):
        FIGURES['min_clearance_m'] = round(cls.truth.min_clearance_m, 3)
        with open(rospy.get_param('~figures_file'), 'w') as f:
            json.dump(FIGURES, f, indent=1)

    def test_1_amcl_converges_from_0_3_m_0_3_rad_off(self):
        guess = [rospy.get_param('/amcl/initial_pose_%s' % k) for k in 'xya']
        start_error = navigation_figures.pose_error(guess, self.truth.get())
        self.assertAlmostEqual(start_error[0], 0.3, delta=0.02)
        self.assertAlmostEqual(start_error[1], 0.3, delta=0.02)
        start_sim, start_wall = rospy.get_time(), time.monotonic()
        converged_in_a_row = 0
        seen = len(self.estimates)
        while converged_in_a_row < 3:
            self.assertLess(rospy.get_time() - start_sim, 60.0, 'AMCL did not converge: %s'
                            % self.estimates[-3:])
            self.driver.send(0.0, 0.8)
            time.sleep(0.05)
            for _, (d, a) in self.estimates[seen:]:
                converged_in_a_row = converged_in_a_row + 1 if (
                    d < CONVERGED_M and a < CONVERGED_RAD) else 0
            seen = len(self.estimates)
        self.driver.stop()
        FIGURES['amcl'] = {'start_error_m_rad': [round(v, 3) for v in start_error],
                           'converged_error_m_rad': [round(v, 3) for v in self.estimates[-1][1]],
                           'sim_s': round(rospy.get_time() - start_sim, 1),
                           'wall_s': round(time.monotonic() - start_wall, 1)}

    def test_2_move_base_reaches_four_goals_round_the_track(self):
        client = actionlib.SimpleActionClient('move_base', MoveBaseAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(60)), 'no move_base')
        FIGURES['goals'] = []
        for x, y, yaw in GOALS:
            goal = MoveBaseGoal()
            goal.target_pose.header.frame_id = 'map'
            goal.target_pose.header.stamp = rospy.Time.now()
            goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
            goal.target_pose.pose.orientation.z = math.sin(yaw / 2)
            goal.target_pose.pose.orientation.w = math.cos(yaw / 2)
            start_sim, start_wall = rospy.get_time(), time.monotonic()
            client.send_goal(goal)
            finished = client.wait_for_result(rospy.Duration(GOAL_TIMEOUT_SIM_S))
            state = client.get_state()
            error = navigation_figures.pose_error((x, y, yaw), self.truth.get())
            FIGURES['goals'].append({'goal': [x, y, round(yaw, 3)],
                                     'error_m_rad': [round(v, 3) for v in error],
                                     'sim_s': round(rospy.get_time() - start_sim, 1),
                                     'wall_s': round(time.monotonic() - start_wall, 1)})
            self.assertTrue(finished and state == GoalStatus.SUCCEEDED,
                            'goal %s: state %d, %s' % ((x, y, yaw), state, FIGURES['goals'][-1]))
            self.assertGreater(self.truth.min_clearance_m, 0.0, 'touched a wall')


if __name__ == '__main__':
    rostest.rosrun('turtlebot3_gazebo', 'navigation_integration', TestNavigation)
