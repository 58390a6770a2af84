#!/usr/bin/python3
"""Key presses in the steering window move the simulated robot: /odom follows."""
import math
import sys
import threading
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry

from mobility_testing import x11
from mobility_testing.waiting import wait_for


def yaw_of(q):
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class OdomWatcher:
    def __init__(self):
        self._lock = threading.Lock()
        self.msg = None
        rospy.Subscriber('/odom', Odometry, self._on_msg, queue_size=10)

    def _on_msg(self, msg):
        with self._lock:
            self.msg = msg

    def position(self):
        with self._lock:
            return None if self.msg is None else (self.msg.pose.pose.position.x,
                                                  self.msg.pose.pose.position.y)

    def yaw(self):
        with self._lock:
            return yaw_of(self.msg.pose.pose.orientation)

    def speed(self):
        with self._lock:
            return None if self.msg is None else self.msg.twist.twist.linear.x


class SteeringSimTest(unittest.TestCase):
    def test_w_drives_forward_and_space_stops(self):
        rospy.init_node('steering_sim_test')
        odom = OdomWatcher()
        window = x11.wait_window('^Robot Steering$', timeout_s=60)
        start = wait_for(odom.position, 60, 'a first /odom message')
        start_yaw = odom.yaw()
        x11.key(window, *['w'] * 5)  # 5 steps of 0.02 m/s: 0.1 m/s forward

        def travelled():
            x, y = odom.position()
            return math.hypot(x - start[0], y - start[1]) > 0.15
        wait_for(travelled, 60, 'the robot 0.15 m away from its start')
        x, y = odom.position()
        heading = math.atan2(y - start[1], x - start[0])
        turn = math.atan2(math.sin(heading - start_yaw), math.cos(heading - start_yaw))
        self.assertLess(abs(turn), 0.2, f'moved towards {heading:.2f} rad, the robot faced '
                                        f'{start_yaw:.2f} rad')

        x11.key(window, 'space')
        wait_for(lambda: abs(odom.speed()) < 0.005, 30, '/odom speed back to zero')
        stopped_at = odom.position()
        rospy.sleep(1.0)  # sim time: the robot stays where it stopped
        x, y = odom.position()
        self.assertLess(math.hypot(x - stopped_at[0], y - stopped_at[1]), 0.01)


if __name__ == '__main__':
    rostest.rosrun('mobility_steering', 'steering_moves_robot', SteeringSimTest, sys.argv)
