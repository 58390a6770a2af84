"""Records geometry_msgs/Twist messages with their wall-clock arrival times (test helper)."""
import threading
import time

import rospy
from geometry_msgs.msg import Twist


class TwistRecorder:
    def __init__(self, topic='/cmd_vel'):
        self._lock = threading.Lock()
        self._records = []
        self._sub = rospy.Subscriber(topic, Twist, self._on_msg, queue_size=100)

    def _on_msg(self, msg):
        with self._lock:
            self._records.append((time.monotonic(), msg.linear.x, msg.angular.z))

    def records(self):
        """List of (arrival_s, linear_x, angular_z)."""
        with self._lock:
            return list(self._records)

    def count(self):
        with self._lock:
            return len(self._records)

    def last(self):
        with self._lock:
            return self._records[-1] if self._records else None

    def since(self, index):
        return self.records()[index:]

    def seen(self, linear_x, angular_z, start=0, tol=1e-6):
        """True once a message with these values arrived at or after record index start."""
        return any(abs(lx - linear_x) < tol and abs(az - angular_z) < tol
                   for _, lx, az in self.since(start))

    def quiet_for(self, seconds):
        last = self.last()
        return last is not None and time.monotonic() - last[0] > seconds

    def wait_connected(self, timeout_s=10.0):
        from mobility_testing.waiting import wait_for
        wait_for(lambda: self._sub.get_num_connections() > 0, timeout_s,
                 'a publisher connected to ' + self._sub.resolved_name)
