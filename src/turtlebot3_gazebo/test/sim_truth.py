"""The Burger's true pose from the simulator, and how close it came to a wall."""
import math
import os
import sys
import threading

import rospy
from gazebo_msgs.msg import ModelStates
from geometry_msgs.msg import Twist

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PACKAGE, 'scripts'))
import navigation_figures  # noqa: E402
import world_obstacles  # noqa: E402

ROBOT = 'turtlebot3_burger'
WALLS = world_obstacles.read_footprints(os.path.join(PACKAGE, 'worlds', 'roundTrack.world'))


def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


class Truth:
    """Follows /gazebo/model_states: pose (x, y, yaw) and the smallest wall clearance seen."""

    def __init__(self):
        self.lock = threading.Lock()
        self.pose = None
        self.min_clearance_m = float('inf')
        self.sub = rospy.Subscriber('/gazebo/model_states', ModelStates, self.on_states,
                                    queue_size=1)

    def on_states(self, msg):
        if ROBOT not in msg.name:
            return
        p = msg.pose[msg.name.index(ROBOT)]
        pose = (p.position.x, p.position.y, yaw_of(p.orientation))
        clearance = navigation_figures.clearance_m(pose[0], pose[1], pose[2], WALLS)
        with self.lock:
            self.pose = pose
            self.min_clearance_m = min(self.min_clearance_m, clearance)

    def get(self):
        with self.lock:
            return self.pose


class Driver:
    """Sends cmd_vel as a person with teleop would."""

    def __init__(self):
        self.pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)

    def send(self, linear_mps, angular_radps):
        t = Twist()
        t.linear.x, t.angular.z = linear_mps, angular_radps
        self.pub.publish(t)

    def stop(self):
        self.send(0.0, 0.0)
