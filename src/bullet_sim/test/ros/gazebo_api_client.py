"""Shared parts of the /gazebo API tests: service proxies, models written for the tests,
pose helpers."""
import math
import threading
import time
import unittest
import xmlrpc.client

import rosgraph
import rospy
from bullet_sim.srv import StepSimulation
from gazebo_msgs import srv as gz
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty

SERVICES = {
    "spawn_urdf_model": gz.SpawnModel, "spawn_sdf_model": gz.SpawnModel,
    "delete_model": gz.DeleteModel, "get_model_state": gz.GetModelState,
    "set_model_state": gz.SetModelState, "get_world_properties": gz.GetWorldProperties,
    "get_model_properties": gz.GetModelProperties, "get_link_state": gz.GetLinkState,
    "set_link_state": gz.SetLinkState, "get_link_properties": gz.GetLinkProperties,
    "get_joint_properties": gz.GetJointProperties,
    "set_model_configuration": gz.SetModelConfiguration,
    "get_physics_properties": gz.GetPhysicsProperties,
    "set_physics_properties": gz.SetPhysicsProperties,
    "apply_body_wrench": gz.ApplyBodyWrench, "apply_joint_effort": gz.ApplyJointEffort,
    "clear_body_wrenches": gz.BodyRequest, "clear_joint_forces": gz.JointRequest,
    "pause_physics": Empty, "unpause_physics": Empty, "reset_simulation": Empty,
    "reset_world": Empty, "step_simulation": StepSimulation,
    "set_link_properties": gz.SetLinkProperties, "set_joint_properties": gz.SetJointProperties,
    "get_light_properties": gz.GetLightProperties,
    "set_light_properties": gz.SetLightProperties, "delete_light": gz.DeleteLight,
}

BOX_MASS_KG = 0.5
BOX_URDF = """<robot name="box">
  <link name="body">
    <inertial><mass value="0.5"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
</robot>"""

# A base (izz 0.2) and a wheel (izz 0.02) on a continuous joint about z.
ROTOR_URDF = """<robot name="rotor">
  <link name="base">
    <inertial><mass value="4"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <joint name="spin" type="continuous"><parent link="base"/><child link="wheel"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/></joint>
  <link name="wheel">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.02"/></inertial>
  </link>
</robot>"""

# A 1 kg, 0.2 m SDF cube whose link sits 0.1 m above its model frame.
SDF_BOX = """<sdf version="1.6"><model name="box"><link name="body"><pose>0 0 0.1 0 0 0</pose>
<inertial><mass>1</mass><inertia><ixx>0.00667</ixx><iyy>0.00667</iyy><izz>0.00667</izz>
<ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>
<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
</link></model></sdf>"""
SDF_STATIC_BOX = SDF_BOX.replace('<model name="box">', '<model name="box"><static>true</static>')


def connect():
    """A proxy per service, named as the service (without /gazebo/)."""
    proxies = {}
    for name, srv_type in SERVICES.items():
        rospy.wait_for_service("/gazebo/" + name, timeout=60)
        proxies[name] = rospy.ServiceProxy("/gazebo/" + name, srv_type)
    return proxies


class GazeboServiceTest(unittest.TestCase):
    """A test of the /gazebo services as node NODE_NAME: each test starts paused, with the
    models it spawns (TEST_MODELS) deleted and the simulation reset. self.gz holds the
    proxies (connect())."""
    NODE_NAME = "gazebo_service_test"
    TEST_MODELS = ()

    @classmethod
    def setUpClass(cls):
        rospy.init_node(cls.NODE_NAME)
        cls.gz = connect()

    def setUp(self):
        self.gz["pause_physics"]()
        for name in self.TEST_MODELS:
            self.gz["delete_model"](name)
        self.gz["reset_simulation"]()

    def call(self, service, *args, **kwargs):
        return self.gz[service](*args, **kwargs)

    def ok(self, service, *args, **kwargs):
        """Calls `service` and checks that it succeeded."""
        response = self.call(service, *args, **kwargs)
        self.assertTrue(response.success, "%s: %s" % (service, response.status_message))
        return response

    def fails(self, service, fragment, *args, **kwargs):
        """Calls `service` and checks that it failed with `fragment` in its message."""
        response = self.call(service, *args, **kwargs)
        self.assertFalse(response.success, "%s accepted a bad request" % service)
        self.assertIn(fragment, response.status_message)
        return response


def yaw_pose(x, y, z=0.0, yaw=0.0):
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = x, y, z
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return pose


def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def rotate(yaw, x, y):
    return (math.cos(yaw) * x - math.sin(yaw) * y, math.sin(yaw) * x + math.cos(yaw) * y)


class Latest:
    """Keeps the messages of a topic."""

    def __init__(self, topic, msg_type):
        self.messages = []
        self.lock = threading.Lock()
        self.sub = rospy.Subscriber(topic, msg_type, self.on_message, queue_size=1000)

    def on_message(self, msg):
        with self.lock:
            self.messages.append(msg)

    def wait_connected(self, timeout_s=30):
        end = time.monotonic() + timeout_s
        while self.sub.get_num_connections() == 0:
            if time.monotonic() > end:
                raise AssertionError("no publisher on " + self.sub.name)
            time.sleep(0.01)

    def count(self):
        with self.lock:
            return len(self.messages)

    def last(self):
        with self.lock:
            return self.messages[-1] if self.messages else None


def simulator_connections(topic, caller_id):
    """The subscribers the simulator's (/bullet_sim) publisher of `topic` is connected to,
    from its own bus information."""
    master = rosgraph.Master(caller_id)
    node = xmlrpc.client.ServerProxy(master.lookupNode("/bullet_sim"))
    _, _, bus = node.getBusInfo(caller_id)
    return [c for c in bus if c[4] == topic and c[2] == "o"]


def wait_for(predicate, what, timeout_s=30):
    end = time.monotonic() + timeout_s
    while not predicate():
        if time.monotonic() > end:
            raise AssertionError("timed out waiting for " + what)
        time.sleep(0.01)
