#!/usr/bin/python3
"""The xqrobot drives on the round track with libgazebo_ros_skid_steer_drive.so.

Stepped by hand (the launch starts paused): a forward command of v = 0.1 m/s turns both
drive wheels (r = 0.0325 m) at v / r = 3.08 rad/s; over 2 s of sim time the robot moves
v t = 0.2 m along its heading (yaw 1.5675: +y), within 3 % for the skid steer's slip; the
odometry is the world pose; robot_state_publisher turns the wheel frames by the joint
angle; a turn command turns it counter-clockwise.
"""
import math
import threading
import time
import unittest

import rospy
import rostest
import tf2_ros
from bullet_sim.srv import StepSimulation
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

WHEEL_RADIUS_M = 0.0325
SPEED_MPS = 0.1
STEPS = 2000  # 2 s of 1 ms steps
YAW = 1.5675
TIMEOUT_S = 60.0


def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


class Latest:
    def __init__(self, topic, msg_type):
        self.msg = None
        self.lock = threading.Lock()
        self.sub = rospy.Subscriber(topic, msg_type, self.store, queue_size=1)

    def store(self, msg):
        with self.lock:
            self.msg = msg

    def get(self):
        with self.lock:
            return self.msg


class XqrobotDrives(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('xqrobot_drives_test')
        for name in ('/gazebo/step_simulation', '/gazebo/get_model_state'):
            rospy.wait_for_service(name, TIMEOUT_S)
        cls.step = rospy.ServiceProxy('/gazebo/step_simulation', StepSimulation)
        cls.state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        deadline = time.monotonic() + TIMEOUT_S
        while not cls.state('xqrobot', '').success:  # spawn_model runs beside the test
            assert time.monotonic() < deadline, 'xqrobot never spawned'
            rospy.rostime.wallsleep(0.05)
        cls.joints = Latest('/joint_states', JointState)
        cls.odom = Latest('/odom', Odometry)
        cls.cmd = rospy.Publisher('/cmd_vel', Twist, queue_size=1, latch=True)
        cls.tf = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf)
        cls.step(500)  # settle on wheels and casters

    def command(self, linear, angular):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        self.cmd.publish(twist)
        # The command has arrived when the wheels turn at its speed.
        left = (linear - angular * 0.16 / 2) / WHEEL_RADIUS_M
        for _ in range(int(TIMEOUT_S / 0.05)):
            self.step(50)
            js = self.joints.get()
            if js and abs(js.velocity[js.name.index('left_wheel_joint')] - left) < 0.05:
                return
            rospy.rostime.wallsleep(0.05)
        self.fail('the wheels never reached %.2f rad/s' % left)

    def pose(self):
        response = self.state('xqrobot', '')
        self.assertTrue(response.success, response.status_message)
        return response.pose

    def test_1_forward_command_moves_it_v_t_along_its_heading(self):
        self.command(SPEED_MPS, 0)
        self.step(300)  # up to speed
        start = self.pose()
        start_js = self.joints.get()
        self.step(STEPS)
        rospy.rostime.wallsleep(0.3)  # the last joint_states and tf of the steps
        end = self.pose()
        end_js = self.joints.get()
        dx, dy = end.position.x - start.position.x, end.position.y - start.position.y
        distance = SPEED_MPS * STEPS * 0.001
        along = dx * math.cos(YAW) + dy * math.sin(YAW)
        across = -dx * math.sin(YAW) + dy * math.cos(YAW)
        self.assertAlmostEqual(along, distance, delta=0.03 * distance)
        self.assertLess(abs(across), 0.01)
        self.assertLess(abs(yaw_of(end.orientation) - YAW), 0.05)
        # Both wheels turned v t / r = 6.15 rad, within the same 3 %.
        for joint in ('left_wheel_joint', 'right_wheel_joint'):
            i = start_js.name.index(joint)
            turned = end_js.position[i] - start_js.position[i]
            self.assertAlmostEqual(turned, distance / WHEEL_RADIUS_M,
                                   delta=0.03 * distance / WHEEL_RADIUS_M)
        # The odometry (world source) is the world pose.
        odom = self.odom.get()
        self.assertEqual((odom.header.frame_id, odom.child_frame_id), ('odom', 'base_link'))
        self.assertAlmostEqual(odom.pose.pose.position.y, end.position.y, delta=0.002)
        # robot_state_publisher turns the wheel's frame about y by the joint's angle.
        angle = end_js.position[end_js.name.index('left_wheel_joint')]
        t = self.tf.lookup_transform('base_link', 'left_wheel_link', rospy.Time(0),
                                     rospy.Duration(5)).transform.rotation
        pitch = 2 * math.atan2(t.y, t.w)
        self.assertAlmostEqual(math.remainder(pitch - angle, 2 * math.pi), 0, delta=0.05)

    def test_2_turn_command_turns_it_counter_clockwise(self):
        self.command(0, 1.0)
        start = yaw_of(self.pose().orientation)
        self.step(500)
        turned = math.remainder(yaw_of(self.pose().orientation) - start, 2 * math.pi)
        # At most the commanded 0.5 rad (the casters slide; the wheels slip a little).
        self.assertGreater(turned, 0.3)
        self.assertLess(turned, 0.5 * 1.03)
        self.command(0, 0)


if __name__ == '__main__':
    rostest.rosrun('xqrobot_description', 'xqrobot_drives', XqrobotDrives)
