#!/usr/bin/python3
"""The simulator's ROS API as empty_world.launch starts it, name for name and type for type,
against gazebo_ros's: what gazebo_ros_api_plugin.cpp (gazebo_ros_pkgs noetic-devel)
advertises in advertiseServices() (services, the model/link state topics, the set_*_state
subscriptions), what its physicsReconfigureThread() starts (a dynamic_reconfigure server in
the node's namespace: set_parameters, parameter_descriptions, parameter_updates), /clock,
and roscpp's logger services of the node named gazebo. With enable_ros_network false,
loadGazeboRosApiPlugin() skips advertiseServices() and the reconfigure thread keeps waiting
for get/set_physics_properties, so /clock and the logger services are all that is left.
gazebo_ros's /gazebo/performance_metrics (only with Gazebo 11.2+, GAZEBO_ROS_HAS_PERFORMANCE_METRICS
in gazebo_ros_api_plugin.h) is not offered: the simulator has no such metrics."""
import time
import unittest

import rosgraph
import rospy
import rosservice
import rostest
from rosgraph_msgs.msg import Clock

CLOCK = {"/clock": "rosgraph_msgs/Clock"}
LOGGERS = {"/gazebo/get_loggers": "roscpp/GetLoggers",
           "/gazebo/set_logger_level": "roscpp/SetLoggerLevel"}
API_TOPICS = {
    "/gazebo/link_states": "gazebo_msgs/LinkStates",
    "/gazebo/model_states": "gazebo_msgs/ModelStates",
    "/gazebo/set_link_state": "gazebo_msgs/LinkState",
    "/gazebo/set_model_state": "gazebo_msgs/ModelState",
    "/gazebo/parameter_descriptions": "dynamic_reconfigure/ConfigDescription",
    "/gazebo/parameter_updates": "dynamic_reconfigure/Config",
}
API_SERVICES = {"/gazebo/" + name: srv for name, srv in {
    "spawn_sdf_model": "gazebo_msgs/SpawnModel",
    "spawn_urdf_model": "gazebo_msgs/SpawnModel",
    "delete_model": "gazebo_msgs/DeleteModel",
    "delete_light": "gazebo_msgs/DeleteLight",
    "get_model_properties": "gazebo_msgs/GetModelProperties",
    "get_model_state": "gazebo_msgs/GetModelState",
    "get_world_properties": "gazebo_msgs/GetWorldProperties",
    "get_joint_properties": "gazebo_msgs/GetJointProperties",
    "get_link_properties": "gazebo_msgs/GetLinkProperties",
    "get_link_state": "gazebo_msgs/GetLinkState",
    "get_light_properties": "gazebo_msgs/GetLightProperties",
    "set_light_properties": "gazebo_msgs/SetLightProperties",
    "get_physics_properties": "gazebo_msgs/GetPhysicsProperties",
    "set_link_properties": "gazebo_msgs/SetLinkProperties",
    "set_physics_properties": "gazebo_msgs/SetPhysicsProperties",
    "set_model_state": "gazebo_msgs/SetModelState",
    "set_model_configuration": "gazebo_msgs/SetModelConfiguration",
    "set_joint_properties": "gazebo_msgs/SetJointProperties",
    "set_link_state": "gazebo_msgs/SetLinkState",
    "pause_physics": "std_srvs/Empty",
    "unpause_physics": "std_srvs/Empty",
    "apply_body_wrench": "gazebo_msgs/ApplyBodyWrench",
    "apply_joint_effort": "gazebo_msgs/ApplyJointEffort",
    "clear_joint_forces": "gazebo_msgs/JointRequest",
    "clear_body_wrenches": "gazebo_msgs/BodyRequest",
    "reset_simulation": "std_srvs/Empty",
    "reset_world": "std_srvs/Empty",
    "set_parameters": "dynamic_reconfigure/Reconfigure",
}.items()}
MARKERS = {"/gazebo/world_markers": "visualization_msgs/MarkerArray",
           "/gazebo/model_markers": "visualization_msgs/MarkerArray"}


class RosApi(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("ros_api_test")
        cls.network = rospy.get_param("~enable_ros_network")
        cls.master = rosgraph.Master(rospy.get_name())
        # The simulator publishes /clock once it has advertised everything.
        rospy.wait_for_message("/clock", Clock, timeout=60)

    def others(self, names):
        """`names` without what the test's own node and /rosout have."""
        mine = rospy.get_name()
        return {n for n in names if not n.startswith(mine + "/") and n != "/rosout"
                and not n.startswith("/rosout/")}

    def topics(self):
        publishers, subscribers, _ = self.master.getSystemState()
        types = dict(self.master.getTopicTypes())
        names = self.others([t for t, _ in publishers] + [t for t, _ in subscribers])
        return {name: types.get(name) for name in names}

    def services(self):
        _, _, services = self.master.getSystemState()
        return {name: rosservice.get_service_type(name)
                for name in self.others([s for s, _ in services])}

    def test_exactly_gazebo_ros_api(self):
        expected_topics = dict(CLOCK, **(API_TOPICS if self.network else {}))
        expected_services = dict(LOGGERS, **(API_SERVICES if self.network else {}))
        self.assertEqual(self.topics(), expected_topics)
        self.assertEqual(self.services(), expected_services)

    def test_markers_while_asked_for(self):
        if not self.network:
            self.skipTest("no /gazebo topic without the ROS network (test_exactly_gazebo_ros_api)")
        rospy.set_param("/gazebo/markers", True)
        self.wait_until(lambda: all(self.topics().get(t) == MARKERS[t] for t in MARKERS),
                        "the marker topics")
        rospy.set_param("/gazebo/markers", False)
        self.wait_until(lambda: not set(MARKERS) & set(self.topics()), "the markers to go")

    def wait_until(self, predicate, what, timeout_s=30):
        end = time.monotonic() + timeout_s
        while not predicate():
            self.assertLess(time.monotonic(), end, "timed out waiting for " + what)
            time.sleep(0.05)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "ros_api", RosApi)
