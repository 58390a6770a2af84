#!/usr/bin/python3
"""roundTrack_simulation.launch (gui:=false): /clock runs, /odom, /scan, /imu and
/joint_states come at the rates of the Burger's Gazebo tags (counted in sim time from
the message stamps), tf reaches the flag, and /cmd_vel moves the robot."""
import math
import threading
import time
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu, JointState, LaserScan

WINDOW_SIM_S = 3.0          # sim seconds of stamps per rate measurement
WALL_DEADLINE_S = 60.0
RATE_TOLERANCE = 0.10
EXPECTED_RATES_HZ = {"/odom": 30.0, "/scan": 5.0, "/imu": 200.0, "/joint_states": 30.0}


class StampRecorder:
    """Keeps the header stamps (sim seconds) of one topic."""

    def __init__(self, topic, msg_type):
        self.lock = threading.Lock()
        self.stamps = []
        self.last = None
        self.sub = rospy.Subscriber(topic, msg_type, self.on_message, queue_size=500)

    def on_message(self, msg):
        with self.lock:
            self.stamps.append(msg.header.stamp.to_sec())
            self.last = msg

    def span_s(self):
        with self.lock:
            return self.stamps[-1] - self.stamps[0] if len(self.stamps) > 1 else 0.0

    def rate_hz(self):
        with self.lock:
            return (len(self.stamps) - 1) / (self.stamps[-1] - self.stamps[0])


def wait_for(condition, what, deadline_s=WALL_DEADLINE_S):
    end = time.monotonic() + deadline_s
    while time.monotonic() < end:
        if condition():
            return
        time.sleep(0.02)
    raise AssertionError("timed out waiting for " + what)


class RoundTrackTopics(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("round_track_topics_test")

    def test_clock_advances(self):
        clocks = []
        sub = rospy.Subscriber("/clock", Clock, lambda m: clocks.append(m.clock.to_sec()))
        wait_for(lambda: len(clocks) > 10 and clocks[-1] - clocks[0] > 0.5, "/clock to advance")
        sub.unregister()
        self.assertTrue(all(b >= a for a, b in zip(clocks, clocks[1:])), "/clock went back")

    def test_sensor_rates(self):
        types = {"/odom": Odometry, "/scan": LaserScan, "/imu": Imu, "/joint_states": JointState}
        recorders = {topic: StampRecorder(topic, types[topic]) for topic in EXPECTED_RATES_HZ}
        for topic, recorder in recorders.items():
            wait_for(lambda: recorder.span_s() >= WINDOW_SIM_S, topic + " stamps")
        for topic, recorder in recorders.items():
            recorder.sub.unregister()
            expected = EXPECTED_RATES_HZ[topic]
            self.assertAlmostEqual(recorder.rate_hz(), expected, delta=expected * RATE_TOLERANCE,
                                   msg=topic + " rate in sim time")
        scan = recorders["/scan"].last
        self.assertEqual(len(scan.ranges), 360)
        self.assertEqual(scan.header.frame_id, "base_scan")
        self.assertEqual(recorders["/imu"].last.header.frame_id, "imu_link")
        self.assertAlmostEqual(recorders["/imu"].last.linear_acceleration.z, 9.8, delta=0.5)
        names = set(recorders["/joint_states"].last.name)
        self.assertTrue({"wheel_left_joint", "wheel_right_joint", "flag_pole_joint"} <= names,
                        "joint_states names: %s" % sorted(names))

    def test_tf_reaches_flag(self):
        buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(buffer)
        transform = buffer.lookup_transform("odom", "flag_link", rospy.Time(0),
                                            rospy.Duration(30.0))
        self.assertEqual(transform.child_frame_id, "flag_link")
        buffer.lookup_transform("base_footprint", "flag_link", rospy.Time(0), rospy.Duration(5.0))

    def test_cmd_vel_moves_odom(self):
        odom = StampRecorder("/odom", Odometry)
        wait_for(lambda: odom.last is not None, "/odom")
        start = odom.last.pose.pose.position
        start_stamp = odom.last.header.stamp.to_sec()
        pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
        command = Twist()
        command.linear.x = 0.15

        def moved_m():
            pub.publish(command)
            position = odom.last.pose.pose.position
            return math.hypot(position.x - start.x, position.y - start.y)

        wait_for(lambda: moved_m() > 0.2, "the robot to drive 0.2 m")
        pub.publish(Twist())
        elapsed_sim_s = odom.last.header.stamp.to_sec() - start_stamp
        self.assertGreater(elapsed_sim_s, 0.2 / 0.15 * 0.9, "drove faster than commanded")
        odom.sub.unregister()


if __name__ == "__main__":
    rostest.rosrun("turtlebot3_gazebo", "round_track_topics", RoundTrackTopics)
