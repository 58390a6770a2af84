#!/usr/bin/python3
"""Two Burgers in the namespaces tb3_0 and tb3_1 (tb3_1 1 m ahead of tb3_0): topics and
tf frames stay separate (frames named with each namespace's tf_prefix), driving one moves
only that one, and they see each other
(lidar, camera) and collide."""
import math
import time
import unittest

import rospy
import rostest
from gazebo_msgs.msg import ModelState
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Image, Imu, LaserScan
from tf2_msgs.msg import TFMessage

from gazebo_api_client import Latest, connect, wait_for, yaw_pose

ROBOTS = {"tb3_0": (0.0, 0.0), "tb3_1": (1.0, 0.0)}
PANEL_URDF = """<robot name="panel"><link name="panel">
  <inertial><origin xyz="0 0 0.2"/><mass value="5"/>
    <inertia ixx="0.2" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial>
  <collision><origin xyz="0 0 0.2"/><geometry><box size="0.1 0.6 0.4"/></geometry></collision>
</link></robot>"""


class MultiRobot(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("multi_robot_test")
        cls.gz = connect()
        urdf = rospy.get_param("/robot_description")
        for name, (x, y) in ROBOTS.items():
            response = cls.gz["spawn_urdf_model"](name, urdf, name, yaw_pose(x, y), "")
            assert response.success, response.status_message

    def setUp(self):
        self.gz["reset_simulation"]()
        self.gz["step_simulation"](300)  # settle on the ground

    def position(self, name):
        response = self.gz["get_model_state"](name, "")
        self.assertTrue(response.success, response.status_message)
        return response.pose.position

    def drive(self, name, linear_mps, steps_of_100):
        pub = rospy.Publisher("/%s/cmd_vel" % name, Twist, queue_size=1, latch=True)
        wait_for(lambda: pub.get_num_connections() > 0, name + "/cmd_vel subscriber")
        command = Twist()
        command.linear.x = linear_mps
        for _ in range(steps_of_100):
            pub.publish(command)
            self.gz["step_simulation"](100)
        pub.publish(Twist())
        self.gz["step_simulation"](500)
        pub.unregister()

    def first(self, topic, msg_type):
        latest = Latest(topic, msg_type)
        latest.wait_connected()
        wait_for(lambda: latest.last() is not None or self.gz["step_simulation"](50) is None,
                 "a message on " + topic)
        latest.sub.unregister()
        return latest.last()

    def test_topics_are_namespaced_and_frames_prefixed(self):
        published = dict(rospy.get_published_topics())
        for name in ROBOTS:
            for topic in ("odom", "scan", "imu", "joint_states", "camera/image_raw"):
                self.assertIn("/%s/%s" % (name, topic), published)
        for topic in ("/odom", "/scan", "/imu", "/joint_states"):
            self.assertNotIn(topic, published)
        for name in ROBOTS:
            odom = self.first("/%s/odom" % name, Odometry)
            self.assertEqual(odom.header.frame_id, name + "/odom")
            self.assertEqual(odom.child_frame_id, name + "/base_footprint")
            self.assertEqual(self.first("/%s/scan" % name, LaserScan).header.frame_id,
                             name + "/base_scan")
            self.assertEqual(self.first("/%s/imu" % name, Imu).header.frame_id,
                             name + "/imu_link")
            self.assertEqual(self.first("/%s/camera/image_raw" % name, Image).header.frame_id,
                             name + "/camera_optical_link")

    def test_driving_one_moves_only_that_one_and_tf_stays_separate(self):
        tf = Latest("/tf", TFMessage)
        odom_1 = Latest("/tb3_1/odom", Odometry)
        tf.wait_connected()
        odom_1.wait_connected()
        start = {name: self.position(name) for name in ROBOTS}
        self.drive("tb3_0", -0.2, 20)  # 2 s backwards, away from tb3_1
        moved_0 = self.position("tb3_0").x - start["tb3_0"].x
        self.assertLess(moved_0, -0.3)
        end_1 = self.position("tb3_1")
        self.assertAlmostEqual(end_1.x, start["tb3_1"].x, delta=0.002)
        self.assertAlmostEqual(end_1.y, start["tb3_1"].y, delta=0.002)
        wait_for(lambda: tf.count() > 10 and odom_1.count() > 10, "tf and tb3_1/odom")
        with tf.lock:
            pairs = {(t.header.frame_id, t.child_frame_id)
                     for m in tf.messages for t in m.transforms}
        self.assertEqual(pairs, {("tb3_0/odom", "tb3_0/base_footprint"),
                                 ("tb3_1/odom", "tb3_1/base_footprint")})
        with odom_1.lock:
            xs = [m.pose.pose.position.x for m in odom_1.messages]
        self.assertLess(max(xs) - min(xs), 0.002)

    def test_lidar_sees_another_robot(self):
        # A panel robot (0.1 m deep, 0.4 m tall) 1 m ahead of tb3_0, tb3_1 out of the way:
        # tb3_0's lidar (0.032 m behind its centre) reads 1 - 0.05 + 0.032 m straight ahead.
        # (A Burger's own 3 cm lidar housing is only met up close: the Burger rests 1 degree
        # nose-up on its caster, so its scan plane rises 1.6 cm per metre.)
        self.gz["set_model_state"](ModelState("tb3_1", yaw_pose(-3, 5), Twist(), ""))
        response = self.gz["spawn_urdf_model"]("panel", PANEL_URDF, "", yaw_pose(1, 0), "")
        self.assertTrue(response.success, response.status_message)
        try:
            self.gz["step_simulation"](300)
            self.assertAlmostEqual(self.first("/tb3_0/scan", LaserScan).ranges[0],
                                   1 - 0.05 + 0.032, delta=0.04)
        finally:
            self.gz["delete_model"]("panel")
        self.gz["step_simulation"](300)
        self.assertTrue(math.isinf(self.first("/tb3_0/scan", LaserScan).ranges[0]))

    def test_camera_sees_the_other_robot(self):
        def centre_rows(image):  # from the horizon down a quarter of the picture
            row = image.step
            return bytes(image.data[int(image.height * 0.5) * row:int(image.height * 0.75) * row])

        with_robot = centre_rows(self.first("/tb3_0/camera/image_raw", Image))
        self.gz["set_model_state"](ModelState("tb3_1", yaw_pose(-3, 5), Twist(), ""))
        self.gz["step_simulation"](300)
        without = centre_rows(self.first("/tb3_0/camera/image_raw", Image))
        changed = sum(1 for a, b in zip(with_robot, without) if abs(a - b) > 30)
        # tb3_1's body (0.14 m wide, 0.93 m ahead) spans 2 atan(0.07 / 0.93) = 0.15 rad of
        # the 1.57 rad view, some 60 of 640 columns, and from the horizon (the camera is
        # 0.305 m up) down to the ground some 100 rows: at least a third of that changes.
        self.assertGreater(changed, 3 * 60 * 100 // 3)

    def test_robots_collide(self):
        # tb3_0 drives at tb3_1, whose wheels hold: it stops against it (base boxes 0.14 m
        # long, so centres 0.14 m apart at contact) and shoves it a little, never through.
        self.drive("tb3_0", 0.2, 80)
        p0, p1 = self.position("tb3_0"), self.position("tb3_1")
        self.assertGreater(p0.x, 0.8, "tb3_0 did not reach tb3_1")
        self.assertGreater(p1.x - ROBOTS["tb3_1"][0], 0.02, "tb3_1 was not pushed")
        self.assertGreater(p1.x - p0.x, 0.13, "tb3_0 went into tb3_1")


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "multi_robot", MultiRobot)
