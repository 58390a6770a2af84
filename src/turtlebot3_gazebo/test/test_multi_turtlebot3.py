#!/usr/bin/python3
"""multi_turtlebot3.launch: each Burger has its topics under /tb3_N/ and its own tf tree
tb3_N/odom -> tb3_N/base_footprint -> ..., a command to one moves only that one, and the
robots see each other with their lidars."""
import math
import threading
import time
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

ROBOTS = ('tb3_0', 'tb3_1', 'tb3_2')
SPAWN_Y = {'tb3_0': 0.0, 'tb3_1': -0.6, 'tb3_2': -1.2}  # all at x 0, facing +y
WALL_DEADLINE_S = 60.0
# Burger geometry (turtlebot3_description): the lidar is 0.032 m behind base_footprint and
# its housing is a cylinder of radius 0.055 m at the same height. Facing +y one behind the
# other 0.6 m apart, the front ray of the rear robot meets the front robot's housing at
# 0.6 - 0.055 = 0.545 m.
FRONT_RAY_TO_HOUSING_M = 0.6 - 0.055


class Latest:
    def __init__(self, topic, msg_type):
        self.lock = threading.Lock()
        self.msg = None
        self.sub = rospy.Subscriber(topic, msg_type, self.on_message, queue_size=5)

    def on_message(self, msg):
        with self.lock:
            self.msg = msg

    def get(self):
        with self.lock:
            return self.msg


def wait_for(condition, what):
    end = time.monotonic() + WALL_DEADLINE_S
    while time.monotonic() < end:
        if condition():
            return
        time.sleep(0.02)
    raise AssertionError('timed out waiting for ' + what)


def stopped_since(odom, stamp):
    """An odometry message newer than stamp with the robot at rest."""
    twist = odom.twist.twist
    return (odom.header.stamp > stamp and abs(twist.linear.x) < 1e-3
            and abs(twist.angular.z) < 1e-3)


class TestMultiTurtlebot3(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.odom = {r: Latest('/%s/odom' % r, Odometry) for r in ROBOTS}
        cls.scan = {r: Latest('/%s/scan' % r, LaserScan) for r in ROBOTS}
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        for robot in ROBOTS:
            wait_for(lambda: cls.odom[robot].get() is not None, '/%s/odom' % robot)
            wait_for(lambda: cls.scan[robot].get() is not None, '/%s/scan' % robot)

    def test_1_topics_and_frames_are_prefixed(self):
        for robot in ROBOTS:
            odom = self.odom[robot].get()
            self.assertEqual(odom.header.frame_id, robot + '/odom')
            self.assertEqual(odom.child_frame_id, robot + '/base_footprint')
            self.assertAlmostEqual(odom.pose.pose.position.y, SPAWN_Y[robot], delta=0.01)
            self.assertEqual(self.scan[robot].get().header.frame_id, robot + '/base_scan')

    def test_2_each_robot_has_one_connected_tree(self):
        for robot in ROBOTS:
            for frame in ('base_scan', 'wheel_left_link', 'flag_link', 'camera_link'):
                wait_for(lambda: self.tf_buffer.can_transform(
                    robot + '/odom', '%s/%s' % (robot, frame), rospy.Time(0)),
                    '%s/odom -> %s/%s' % (robot, robot, frame))
            # base_scan sits 0.032 m behind base_footprint and 0.182 m above the ground.
            t = self.tf_buffer.lookup_transform(robot + '/base_footprint', robot + '/base_scan',
                                                rospy.Time(0)).transform.translation
            self.assertAlmostEqual(t.x, -0.032, places=3)
            self.assertAlmostEqual(t.z, 0.182, places=3)
        self.assertFalse(self.tf_buffer.can_transform('odom', 'base_footprint', rospy.Time(0)),
                         'an unprefixed tree exists next to the prefixed ones')

    def test_3_robots_see_each_other(self):
        for rear in ('tb3_1', 'tb3_2'):
            front_ray = self.scan[rear].get().ranges[0]
            self.assertAlmostEqual(front_ray, FRONT_RAY_TO_HOUSING_M, delta=0.04,
                                   msg='%s front ray %.3f' % (rear, front_ray))

    def test_4_a_command_moves_only_its_robot(self):
        before = {r: self.odom[r].get().pose.pose.position for r in ROBOTS}
        pub = rospy.Publisher('/tb3_0/cmd_vel', Twist, queue_size=1)
        wait_for(lambda: pub.get_num_connections() > 0, 'the simulator on /tb3_0/cmd_vel')
        command = Twist()
        command.linear.x = 0.1
        start = rospy.get_time()
        while rospy.get_time() - start < 2.0:  # sim seconds
            pub.publish(command)
            rospy.sleep(0.1)
        pub.publish(Twist())
        stop = rospy.Time.now()
        wait_for(lambda: stopped_since(self.odom['tb3_0'].get(), stop), 'tb3_0 at rest')
        after = {r: self.odom[r].get().pose.pose.position for r in ROBOTS}
        moved = after['tb3_0'].y - before['tb3_0'].y
        self.assertGreater(moved, 0.15)  # about 0.2 m forward (+y) at 0.1 m/s for 2 s
        self.assertLess(moved, 0.25)
        for robot in ('tb3_1', 'tb3_2'):
            shift = math.hypot(after[robot].x - before[robot].x, after[robot].y - before[robot].y)
            self.assertLess(shift, 0.005, robot)


if __name__ == '__main__':
    rospy.init_node('test_multi_turtlebot3')
    rostest.rosrun('turtlebot3_gazebo', 'multi_turtlebot3', TestMultiTurtlebot3)
