#!/usr/bin/python3
"""The /gazebo services of bullet_sim_node, on a simulation that starts paused:
step, pause/unpause, get/set model state, reset_world, reset_simulation, spawn and
delete, and /cmd_vel driving the robot while stepped."""
import math
import threading
import time
import unittest

import rospy
import rostest
from bullet_sim.srv import StepSimulation
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import DeleteModel, GetModelState, SetModelState, SpawnModel
from geometry_msgs.msg import Pose, Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from std_srvs.srv import Empty

ROBOT = "burger"
SPAWN_X_M, SPAWN_Y_M = 0.5, -0.25
STEP_S = 0.001


def service(name, srv_type):
    rospy.wait_for_service(name, timeout=60)
    return rospy.ServiceProxy(name, srv_type)


def yaw_pose(x, y, yaw):
    pose = Pose()
    pose.position.x, pose.position.y = x, y
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return pose


def yaw_of(orientation):
    q = orientation
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


class Services(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("services_test")
        cls.step = service("/gazebo/step_simulation", StepSimulation)
        cls.pause = service("/gazebo/pause_physics", Empty)
        cls.unpause = service("/gazebo/unpause_physics", Empty)
        cls.reset_simulation = service("/gazebo/reset_simulation", Empty)
        cls.reset_world = service("/gazebo/reset_world", Empty)
        cls.get_state = service("/gazebo/get_model_state", GetModelState)
        cls.set_state = service("/gazebo/set_model_state", SetModelState)
        cls.spawn = service("/gazebo/spawn_urdf_model", SpawnModel)
        cls.delete = service("/gazebo/delete_model", DeleteModel)

    def setUp(self):
        self.pause()
        self.reset_simulation()

    def state(self, name=ROBOT):
        response = self.get_state(name, "")
        self.assertTrue(response.success, response.status_message)
        return response

    def test_step_advances_exactly(self):
        before = self.step(0).sim_time.to_sec()
        response = self.step(250)
        self.assertTrue(response.success, response.status_message)
        self.assertAlmostEqual(response.sim_time.to_sec() - before, 250 * STEP_S, places=6)
        self.assertAlmostEqual(self.state().header.stamp.to_sec(), response.sim_time.to_sec(),
                               places=6)

    def test_step_refused_while_running(self):
        self.unpause()
        try:
            self.assertFalse(self.step(10).success)
        finally:
            self.pause()

    def test_pause_stops_and_unpause_runs(self):
        start_s = self.state().header.stamp.to_sec()
        self.unpause()
        end = time.monotonic() + 30
        while self.state().header.stamp.to_sec() < start_s + 0.2:
            self.assertLess(time.monotonic(), end, "sim time did not advance after unpause")
        self.pause()
        paused_s = self.state().header.stamp.to_sec()
        time.sleep(0.3)  # a window in which a running simulation would advance
        self.assertEqual(self.state().header.stamp.to_sec(), paused_s)

    def test_spawn_pose_and_get_state(self):
        self.step(500)
        pose = self.state().pose
        self.assertAlmostEqual(pose.position.x, SPAWN_X_M, delta=0.01)
        self.assertAlmostEqual(pose.position.y, SPAWN_Y_M, delta=0.01)
        self.assertAlmostEqual(yaw_of(pose.orientation), 0.0, delta=0.02)
        self.assertFalse(self.get_state("no_such_robot", "").success)

    def test_set_state_teleports(self):
        target = ModelState(model_name=ROBOT, pose=yaw_pose(2.0, 1.0, 1.0), twist=Twist())
        self.assertTrue(self.set_state(target).success)
        self.step(200)
        pose = self.state().pose
        self.assertAlmostEqual(pose.position.x, 2.0, delta=0.02)
        self.assertAlmostEqual(pose.position.y, 1.0, delta=0.02)
        self.assertAlmostEqual(yaw_of(pose.orientation), 1.0, delta=0.02)
        target.model_name = "no_such_robot"
        self.assertFalse(self.set_state(target).success)

    def test_reset_world_and_simulation(self):
        self.set_state(ModelState(model_name=ROBOT, pose=yaw_pose(-1.0, 2.0, 2.0)))
        self.step(100)
        self.reset_world()
        self.step(100)
        response = self.state()
        self.assertAlmostEqual(response.pose.position.x, SPAWN_X_M, delta=0.01)
        self.assertAlmostEqual(response.pose.position.y, SPAWN_Y_M, delta=0.01)
        self.assertAlmostEqual(response.header.stamp.to_sec(), 0.2, places=6)
        self.set_state(ModelState(model_name=ROBOT, pose=yaw_pose(-1.0, 2.0, 2.0)))
        self.reset_simulation()
        response = self.state()
        self.assertEqual(response.header.stamp.to_sec(), 0.0)
        self.assertAlmostEqual(response.pose.position.x, SPAWN_X_M, delta=0.01)
        self.assertAlmostEqual(response.pose.position.y, SPAWN_Y_M, delta=0.01)

    def test_spawn_and_delete(self):
        urdf = rospy.get_param("/robot_description")
        response = self.spawn("second", urdf, "second", yaw_pose(-2.0, 0.0, 0.0), "world")
        self.assertTrue(response.success, response.status_message)
        self.step(100)
        self.assertAlmostEqual(self.state("second").pose.position.x, -2.0, delta=0.02)
        self.assertFalse(self.spawn("second", urdf, "second", Pose(), "").success)
        self.assertFalse(self.spawn("third", "<robot", "", Pose(), "").success)
        self.assertTrue(self.delete("second").success)
        self.assertFalse(self.delete("second").success)
        self.assertFalse(self.get_state("second", "").success)

    def test_cmd_vel_drives_while_stepping(self):
        odom = []
        lock = threading.Lock()

        def on_odom(msg):
            with lock:
                odom.append(msg)

        sub = rospy.Subscriber("/odom", Odometry, on_odom)
        pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
        command = Twist()
        command.linear.x = 0.2
        end = time.monotonic() + 30
        while pub.get_num_connections() == 0 or sub.get_num_connections() == 0:
            self.assertLess(time.monotonic(), end, "no connection to the simulator")
            time.sleep(0.01)
        for _ in range(40):
            pub.publish(command)
            self.step(100)
        pub.publish(Twist())
        for _ in range(5):
            self.step(100)
        pose = self.state().pose
        self.assertGreater(pose.position.x - SPAWN_X_M, 0.4)
        self.assertAlmostEqual(pose.position.y, SPAWN_Y_M, delta=0.03)
        end = time.monotonic() + 10
        while True:
            with lock:
                latest = odom[-1] if odom else None
            if latest is not None and math.hypot(
                    latest.pose.pose.position.x - odom[0].pose.pose.position.x,
                    latest.pose.pose.position.y - odom[0].pose.pose.position.y) > 0.4:
                break
            self.assertLess(time.monotonic(), end, "/odom did not follow the robot")
            time.sleep(0.01)
        sub.unregister()

    def test_nan_command_is_dropped_with_warning(self):
        warnings = []
        sub = rospy.Subscriber("/rosout", Log, lambda m: warnings.append(m.msg)
                               if m.level == Log.WARN and "cmd_vel" in m.msg else None)
        pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
        command = Twist()
        command.linear.x = float("nan")
        command.angular.z = 0.5
        start_x = self.state().pose.position.x
        end = time.monotonic() + 30
        while not warnings:
            self.assertLess(time.monotonic(), end, "no warning about the NaN command")
            pub.publish(command)
            self.step(20)
        self.step(200)
        self.assertIn("linear.x", warnings[0])
        pose = self.state().pose
        self.assertAlmostEqual(pose.position.x, start_x, delta=0.002)
        self.assertAlmostEqual(yaw_of(pose.orientation), 0.0, delta=0.01)
        sub.unregister()


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "services", Services)
