#!/usr/bin/python3
"""The simulator started by empty_world.launch (paused, no robot), and spawn_model's exit
codes and effects as Gazebo users rely on them."""
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest

import rospy
import rostest
from gazebo_msgs.srv import GetJointProperties, GetModelState, GetWorldProperties
from geometry_msgs.msg import Point, Pose, Quaternion

from gazebo_ros import gazebo_interface

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'overlay'))
import overlay_workspace  # noqa: E402


def spawn_model(*args, **kwargs):
    return subprocess.run(['rosrun', 'gazebo_ros', 'spawn_model'] + list(args),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=60, **kwargs)


def start_spawn_model(*args, **kwargs):
    return subprocess.Popen(['rosrun', 'gazebo_ros', 'spawn_model'] + list(args),
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, **kwargs)


class TestEmptyWorld(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.wait_for_service('/gazebo/get_world_properties', 60)
        cls.world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
        cls.model_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        cls.joint = rospy.ServiceProxy('/gazebo/get_joint_properties', GetJointProperties)
        cls.tmp = tempfile.mkdtemp(prefix='gazebo_ros_empty_world_')
        cls.addClassCleanup(shutil.rmtree, cls.tmp, ignore_errors=True)
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

    def test_6_help_exits_0(self):
        out = spawn_model('-h')
        self.assertEqual(out.returncode, 0, out.stdout)
        self.assertTrue(out.stdout.startswith('usage: spawn_model [-h] (-urdf | -sdf)'))
        self.assertIn('-J JOINT_NAME JOINT_POSITION', out.stdout)

    def test_7_missing_parameter_exits_1_naming_it(self):
        out = spawn_model('-urdf', '-param', 'no_such_description', '-model', 'ghost')
        self.assertEqual(out.returncode, 1)
        self.assertIn('parameter /no_such_description does not exist or is empty', out.stdout)

    def wait_until_listed(self, model, listed=True):
        deadline = rospy.get_time() + 30
        while (model in self.world().model_names) != listed:
            self.assertLess(rospy.get_time(), deadline, '%s listed: %s' % (model, not listed))

    def test_8_stdin_and_bond_delete_the_model_on_stop(self):
        with open(self.urdf) as urdf:
            spawner = start_spawn_model('-urdf', '-stdin', '-model', 'bonded', '-x', '-1',
                                        '-b', stdin=urdf)
        self.wait_until_listed('bonded')
        self.assertIsNone(spawner.poll())  # held until stopped
        spawner.send_signal(signal.SIGINT)
        self.assertEqual(spawner.wait(timeout=30), 0, spawner.stdout.read())
        self.assertNotIn('bonded', self.world().model_names)

    def test_9_wait_spawns_once_the_other_model_exists(self):
        waiting = start_spawn_model('-urdf', '-file', self.urdf, '-model', 'follower', '-x',
                                    '3', '-wait', 'leader')
        # Not spawned while the leader is missing (the world is asked every 0.1 s).
        self.wait_until_listed('follower', listed=False)
        self.assertIsNone(waiting.poll(), waiting.stdout.read() if waiting.poll() else '')
        out = spawn_model('-urdf', '-file', self.urdf, '-model', 'leader', '-x', '-3')
        self.assertEqual(out.returncode, 0, out.stdout)
        self.assertEqual(waiting.wait(timeout=30), 0, waiting.stdout.read())
        self.assertIn('follower', self.world().model_names)

    def test_9b_the_python_api_spawns_and_sets_joints(self):
        with open(self.urdf) as urdf:
            xml = urdf.read()
        pose = Pose(Point(0, -3, 0), Quaternion(0, 0, 0, 1))
        self.assertTrue(gazebo_interface.spawn_urdf_model_client(
            'py_probe', xml, '/', pose, '', '/gazebo'))
        self.assertIn('py_probe', self.world().model_names)
        self.assertTrue(gazebo_interface.set_model_configuration_client(
            'py_probe', '', ['left_wheel_joint'], [0.4], '/gazebo'))
        self.assertFalse(gazebo_interface.spawn_urdf_model_client(
            'py_probe', xml, '/', pose, '', '/gazebo'))  # the name is taken


if __name__ == '__main__':
    rospy.init_node('test_empty_world')
    rostest.rosrun('gazebo_ros', 'empty_world_spawn_model', TestEmptyWorld)
