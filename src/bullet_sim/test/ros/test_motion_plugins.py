#!/usr/bin/python3
"""libgazebo_ros_planar_move.so and libgazebo_ros_joint_state_publisher.so through their topics.

A 2 kg box `body` with a rotor on continuous joint `spin` and another on `tilt` is spawned
in namespace `bot` at (0, 0, 1), turned 0.5 rad, in a world without gravity. Its planar move
plugin (odometryRate 20) is sent x 0.2 m/s, y 0.1 m/s on /bot/cmd_vel: in the box's yaw
frame it moves 0.2 and 0.1 m per second of sim time. Its joint state publisher names `spin`
alone at 50 Hz. 1000 steps of 1 ms then give 20 odometry messages, odom -> base_footprint
on /tf with each, and 50 joint states that name `spin` only.
"""
import math
import time

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
from spawned_model_test import TIMEOUT_S, SpawnedModelTest

INERTIA = '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
ROTOR = """<link name="{0}_rotor"><inertial><mass value="0.1"/>{1}</inertial></link>
<joint name="{0}" type="continuous"><parent link="body"/><child link="{0}_rotor"/>
<axis xyz="0 0 1"/></joint>"""
BOT = ('<robot name="bot"><link name="body"><inertial><mass value="2"/>' + INERTIA +
       '</inertial><collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>'
       '</link>' + ROTOR.format('spin', INERTIA) + ROTOR.format('tilt', INERTIA) +
       """<gazebo><plugin name="move" filename="libgazebo_ros_planar_move.so">
<odometryRate>20</odometryRate></plugin>
<plugin name="joints" filename="libgazebo_ros_joint_state_publisher.so">
<jointName>spin</jointName><updateRate>50</updateRate></plugin></gazebo></robot>""")
YAW = 0.5


class MotionPlugins(SpawnedModelTest):
    node_name = 'motion_plugins_test'

    def setUp(self):
        super().setUp()
        self.spawn('bot', BOT, 1.0, YAW)
        self.odoms, self.joints, self.tfs = [], [], []
        self.subs = [
            rospy.Subscriber('/bot/odom', Odometry, self.keep(self.odoms), queue_size=1000),
            rospy.Subscriber('/bot/joint_states', JointState, self.keep(self.joints),
                             queue_size=1000),
            rospy.Subscriber('/tf', TFMessage, self.keep(self.tfs), queue_size=1000)]

    def keep(self, into):
        def store(msg):
            with self.lock:
                into.append(msg)
        return store

    def test_planar_move_and_joint_states(self):
        command = rospy.Publisher('/bot/cmd_vel', Twist, queue_size=1, latch=True)
        self.wait_for_connection(command)
        for sub in self.subs:
            self.wait_for_connection(sub)
        twist = Twist()
        twist.linear.x, twist.linear.y = 0.2, 0.1
        command.publish(twist)
        # The command has arrived when the odometry moves; from then on, 1000 steps.
        self.step_until(50, lambda: self.odoms and self.odoms[-1].twist.twist.linear.x > 0.1,
                        'the box never moved')
        with self.lock:
            start = self.odoms[-1]
        self.step(1000)
        end = start.header.stamp + rospy.Duration(1.005)  # 1 s, stamps rounded to ns

        def after_start(messages):
            with self.lock:
                return [m for m in messages if start.header.stamp < m.header.stamp <= end]

        deadline = time.monotonic() + TIMEOUT_S
        while len(after_start(self.odoms)) < 20 or len(after_start(self.joints)) < 50:
            self.assertLess(time.monotonic(), deadline, 'too few messages')
            time.sleep(0.02)
        time.sleep(0.3)
        odoms, joints = after_start(self.odoms), after_start(self.joints)
        with self.lock:
            tfs = [t for m in self.tfs for t in m.transforms
                   if start.header.stamp < t.header.stamp <= end]
        self.assertEqual(len(odoms), 20)  # odometryRate 20 over 1 s of sim time
        self.assertEqual(len(joints), 50)  # updateRate 50
        self.assertTrue(all(j.name == ['spin'] for j in joints))
        self.assertEqual(len(joints[-1].position), 1)
        self.assertEqual(len(joints[-1].velocity), 1)
        odom_tfs = [t for t in tfs if t.child_frame_id == 'base_footprint']
        self.assertEqual(len(odom_tfs), 20)
        self.assertEqual(odom_tfs[-1].header.frame_id, 'odom')
        last = odoms[-1]
        self.assertEqual((last.header.frame_id, last.child_frame_id), ('odom', 'base_footprint'))
        dt = (last.header.stamp - start.header.stamp).to_sec()
        self.assertAlmostEqual(dt, 1.0, delta=1e-6)
        self.assertEqual(odom_tfs[-1].header.stamp, last.header.stamp)
        # Moved (0.2, 0.1) m/s * dt in the box's frame, turned YAW in the world.
        dx = last.pose.pose.position.x - start.pose.pose.position.x
        dy = last.pose.pose.position.y - start.pose.pose.position.y
        c, s = math.cos(YAW), math.sin(YAW)
        self.assertAlmostEqual(c * dx + s * dy, 0.2 * dt, delta=1e-6)
        self.assertAlmostEqual(-s * dx + c * dy, 0.1 * dt, delta=1e-6)
        self.assertAlmostEqual(last.twist.twist.linear.x, 0.2, delta=1e-6)
        self.assertAlmostEqual(last.twist.twist.linear.y, 0.1, delta=1e-6)
        self.assertEqual(last.pose.pose.position.z, 0.0)  # as Gazebo's message
        self.assertAlmostEqual(odom_tfs[-1].transform.translation.z, 1.0, delta=1e-6)
        self.assertEqual(last.pose.covariance[35], 0.001)


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'motion_plugins', MotionPlugins)
