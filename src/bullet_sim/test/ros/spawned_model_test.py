"""What the rostests of model plugins share: a test node, the step service, a model spawned
from URDF text into its own namespace, and waiting for a topic's connection."""
import math
import threading
import time
import unittest

import rospy
from bullet_sim.srv import StepSimulation
from gazebo_msgs.srv import SpawnModel
from geometry_msgs.msg import Pose

TIMEOUT_S = 30.0


class SpawnedModelTest(unittest.TestCase):
    """setUp starts node `node_name` and waits for the spawn and step services: `self.step`
    takes N physics steps; `self.lock` guards what subscribers store."""
    node_name = 'spawned_model_test'

    def setUp(self):
        rospy.init_node(self.node_name)
        for name in ('/gazebo/spawn_urdf_model', '/gazebo/step_simulation'):
            rospy.wait_for_service(name, TIMEOUT_S)
        self.step = rospy.ServiceProxy('/gazebo/step_simulation', StepSimulation)
        self.lock = threading.Lock()

    def spawn(self, name, urdf, z, yaw=0.0):
        """Spawns `urdf` as model `name` in namespace `name` at (0, 0, z), turned by `yaw`."""
        pose = Pose()
        pose.position.z = z
        pose.orientation.z = math.sin(yaw / 2)
        pose.orientation.w = math.cos(yaw / 2)
        spawn = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
        response = spawn(name, urdf, name, pose, '')
        self.assertTrue(response.success, response.status_message)

    def wait_for_connection(self, topic_object):
        deadline = time.monotonic() + TIMEOUT_S
        while topic_object.get_num_connections() == 0:
            self.assertLess(time.monotonic(), deadline, 'no connection')
            time.sleep(0.02)

    def step_until(self, steps, arrived, what):
        """Steps `steps` at a time until arrived() (read under the lock) is true: a
        command sent on a topic has reached the simulator once its effect shows."""
        deadline = time.monotonic() + TIMEOUT_S
        while True:
            self.step(steps)
            time.sleep(0.01)
            with self.lock:
                if arrived():
                    return
            self.assertLess(time.monotonic(), deadline, what)
