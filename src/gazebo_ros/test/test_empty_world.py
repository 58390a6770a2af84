#!/usr/bin/python3
"""The simulator started by empty_world.launch (paused, no robot), and spawn_model's exit
codes and effects as Gazebo users rely on them."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import rospy
import rostest
from gazebo_msgs.srv import GetJointProperties, GetModelState, GetWorldProperties

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'overlay'))
import overlay_workspace  # noqa: E402


def spawn_model(*args):
    return subprocess.run(['rosrun', 'gazebo_ros', 'spawn_model'] + list(args),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=60)


class TestEmptyWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.wait_for_service('/gazebo/get_world_properties', 60)
        cls.world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
        cls.model_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        cls.joint = rospy.ServiceProxy('/gazebo/get_joint_properties', GetJointProperties)
        cls.tmp = tempfile.mkdtemp()
        cls.urdf = os.path.join(cls.tmp, 'probe.urdf')
        with open(cls.urdf, 'w') as out:
            out.write(overlay_workspace.ROBOT_URDF)

    def test_1_starts_paused_with_no_robot(self):
        world = self.world()
        self.assertTrue(world.success)
        self.assertNotIn('probe', world.model_names)
        self.assertEqual(world.sim_time, 0.0)

    def test_2_spawns_at_the_pose_with_joints_then_unpauses(self):
        out = spawn_model('-urdf', '-file', self.urdf, '-model', 'probe', '-x', '1.0', '-y',
                          '2.0', '-Y', '0.5', '-J', 'left_wheel_joint', '0.7', '-unpause')
        self.assertEqual(out.returncode, 0, out.stdout)
        self.assertIn('probe', self.world().model_names)
        state = self.model_state('probe', 'world')
        self.assertTrue(state.success, state.status_message)
        self.assertAlmostEqual(state.pose.position.x, 1.0, delta=0.005)
        self.assertAlmostEqual(state.pose.position.y, 2.0, delta=0.005)
        q = state.pose.orientation
        yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        self.assertAlmostEqual(yaw, 0.5, delta=0.005)
        wheel = self.joint('left_wheel_joint')
        self.assertTrue(wheel.success, wheel.status_message)
        self.assertAlmostEqual(wheel.position[0], 0.7, delta=0.02)
        start = self.world().sim_time
        deadline = rospy.get_time() + 30  # sim time: only advances once unpaused
        while self.world().sim_time <= start:
            self.assertLess(rospy.get_time(), deadline)

    def test_3_wrong_argument_prints_usage_and_exits_1(self):
        out = spawn_model('-urdf', '-file', self.urdf, '-model', 'x', '-speed', '2')
        self.assertEqual(out.returncode, 1)
        self.assertIn('usage: spawn_model', out.stdout)
        self.assertIn('unrecognized arguments: -speed 2', out.stdout)

    def test_4_missing_file_exits_1_naming_it(self):
        out = spawn_model('-urdf', '-file', '/nonexistent/robot.urdf', '-model', 'ghost')
        self.assertEqual(out.returncode, 1)
        self.assertIn('specified file /nonexistent/robot.urdf does not exist', out.stdout)

    def test_5_a_refused_model_exits_1_with_the_simulators_reason(self):
        out = spawn_model('-urdf', '-file', self.urdf, '-model', 'probe')
        self.assertEqual(out.returncode, 1)
        self.assertIn("probe", out.stdout)
        self.assertIn('Spawn service failed', out.stdout)


if __name__ == '__main__':
    rospy.init_node('test_empty_world')
    rostest.rosrun('gazebo_ros', 'empty_world_spawn_model', TestEmptyWorld)
