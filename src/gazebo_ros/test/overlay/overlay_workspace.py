"""Writes catkin workspaces the way a user's clone of Gazebo-based packages looks, to be
built on top of this workspace (`source devel/setup.bash`, then `catkin_make`)."""
import os
import textwrap

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>A package written for Gazebo.</description>
  <maintainer email="user@example.invalid">user</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend>
  <depend>rospy</depend>
  <depend>gazebo_ros</depend>
  <depend>gazebo_msgs</depend>
  <depend>geometry_msgs</depend>
  <export>
    <gazebo_ros gazebo_model_path="${{prefix}}/models"/>
  </export>
</package>
'''

# The usual CMakeLists of a simulation package: Gazebo found for its variables only,
# a plain roscpp node built with them.
CMAKELISTS = '''cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS roscpp gazebo_ros gazebo_msgs geometry_msgs)
find_package(gazebo REQUIRED)
catkin_package(DEPENDS gazebo CATKIN_DEPENDS gazebo_ros gazebo_msgs)
include_directories(${{catkin_INCLUDE_DIRS}} ${{GAZEBO_INCLUDE_DIRS}})
link_directories(${{GAZEBO_LIBRARY_DIRS}})
set(CMAKE_CXX_FLAGS "${{CMAKE_CXX_FLAGS}} ${{GAZEBO_CXX_FLAGS}}")
add_executable(model_state_client src/model_state_client.cpp)
target_link_libraries(model_state_client ${{catkin_LIBRARIES}} ${{GAZEBO_LIBRARIES}})
{extra}
'''

# A C++ client of gazebo_msgs/GetModelState: prints "x y yaw" of a model, exits 1 on failure.
CLIENT_CPP = r'''#include <cmath>
#include <cstdio>
#include <gazebo_msgs/GetModelState.h>
#include <ros/ros.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "model_state_client");
  ros::NodeHandle nh;
  if (argc < 2 || !ros::service::waitForService("/gazebo/get_model_state", ros::Duration(30)))
    return 1;
  gazebo_msgs::GetModelState srv;
  srv.request.model_name = argv[1];
  if (!ros::service::call("/gazebo/get_model_state", srv) || !srv.response.success) return 1;
  const auto& q = srv.response.pose.orientation;
  const double yaw = std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
  std::printf("%.4f %.4f %.4f\n", srv.response.pose.position.x, srv.response.pose.position.y,
              yaw);
  return 0;
}
'''

MODEL_CONFIG = '''<?xml version="1.0"?>
<model>
  <name>{name}</name>
  <version>1.0</version>
  <sdf version="1.6">model.sdf</sdf>
  <description>A crate.</description>
</model>
'''

CRATE_SDF = '''<?xml version="1.0"?>
<sdf version="1.6">
  <model name="crate">
    <static>true</static>
    <link name="body">
      <pose>0 0 0.2 0 0 0</pose>
      <collision name="c"><geometry><box><size>0.4 0.4 0.4</size></box></geometry></collision>
      <visual name="v"><geometry><box><size>0.4 0.4 0.4</size></box></geometry></visual>
    </link>
  </model>
</sdf>
'''

WORLD = '''<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <include><uri>model://sun</uri></include>
    <include><uri>model://ground_plane</uri></include>
    <include>
      <uri>model://overlay_crate</uri>
      <name>crate_1</name>
      <pose>2 0 0 0 0 0</pose>
    </include>
  </world>
</sdf>
'''

# A small two-wheeled robot with Gazebo's diff drive plugin, as a course package writes it.
ROBOT_URDF = '''<?xml version="1.0"?>
<robot name="probe">
  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/><origin xyz="0 0 0.05"/>
  </joint>
  <link name="base_link">
    <inertial><mass value="1.0"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><origin xyz="-0.05 0 0"/><geometry><box size="0.2 0.15 0.05"/></geometry></collision>
    <visual><origin xyz="-0.05 0 0"/><geometry><box size="0.2 0.15 0.05"/></geometry></visual>
  </link>
  <link name="left_wheel">
    <inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    <collision><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
  </link>
  <link name="right_wheel">
    <inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    <collision><geometry><cylinder radius="0.05" length="0.02"/></geometry></collision>
  </link>
  <joint name="left_wheel_joint" type="continuous">
    <parent link="base_link"/><child link="left_wheel"/>
    <origin xyz="0 0.09 0" rpy="-1.5708 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="right_wheel_joint" type="continuous">
    <parent link="base_link"/><child link="right_wheel"/>
    <origin xyz="0 -0.09 0" rpy="-1.5708 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <link name="caster">
    <inertial><mass value="0.01"/><inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/></inertial>
    <collision><geometry><sphere radius="0.025"/></geometry></collision>
  </link>
  <joint name="caster_joint" type="fixed">
    <parent link="base_link"/><child link="caster"/><origin xyz="-0.13 0 -0.025"/>
  </joint>
  <gazebo reference="caster"><mu1>0.0</mu1><mu2>0.0</mu2></gazebo>
  <gazebo>
    <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
      <leftJoint>left_wheel_joint</leftJoint>
      <rightJoint>right_wheel_joint</rightJoint>
      <wheelSeparation>0.18</wheelSeparation>
      <wheelDiameter>0.1</wheelDiameter>
      <wheelTorque>5</wheelTorque>
      <commandTopic>cmd_vel</commandTopic>
      <odometryTopic>odom</odometryTopic>
      <odometryFrame>odom</odometryFrame>
      <robotBaseFrame>base_footprint</robotBaseFrame>
      <updateRate>30</updateRate>
    </plugin>
  </gazebo>
</robot>
'''

# The launch file exactly as it would be written for Gazebo.
LAUNCH = '''<?xml version="1.0"?>
<launch>
  <include file="$(find gazebo_ros)/launch/empty_world.launch">
    <arg name="world_name" value="$(find {name})/worlds/crates.world"/>
    <arg name="paused" value="false"/>
    <arg name="use_sim_time" value="true"/>
    <arg name="gui" value="false"/>
    <arg name="headless" value="true"/>
    <arg name="debug" value="false"/>
  </include>
  <param name="robot_description" textfile="$(find {name})/urdf/probe.urdf"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn_probe"
        args="-urdf -model probe -x 0.5 -y -0.25 -z 0.0 -Y 0.3 -param robot_description"/>
</launch>
'''

TEST_LAUNCH = '''<?xml version="1.0"?>
<launch>
  <include file="$(find {name})/launch/probe_world.launch"/>
  <test test-name="overlay_clients" pkg="{name}" type="check_clients.py" time-limit="90"/>
</launch>
'''

# A Python client of gazebo_msgs as course scripts use it, run as the rostest's test node.
CHECK_CLIENTS = '''#!/usr/bin/python3
import subprocess
import unittest

import rospy
import rostest
from gazebo_msgs.srv import GetModelState, GetWorldProperties


class Clients(unittest.TestCase):
    def test_python_and_cpp_clients(self):
        rospy.wait_for_service('/gazebo/get_model_state', 60)
        world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
        deadline = rospy.get_time() + 60
        while 'probe' not in world().model_names:
            self.assertLess(rospy.get_time(), deadline, 'probe never spawned')
            rospy.sleep(0.1)
        self.assertIn('crate_1', world().model_names)
        state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)('crate_1', '')
        self.assertTrue(state.success, state.status_message)
        self.assertAlmostEqual(state.pose.position.x, 2.0, places=3)
        out = subprocess.run(['rosrun', '{name}', 'model_state_client', 'probe'],
                             stdout=subprocess.PIPE, universal_newlines=True, timeout=60)
        self.assertEqual(out.returncode, 0)
        x, y, yaw = (float(v) for v in out.stdout.split())
        self.assertAlmostEqual(x, 0.5, delta=0.01)
        self.assertAlmostEqual(y, -0.25, delta=0.01)
        self.assertAlmostEqual(yaw, 0.3, delta=0.01)


if __name__ == '__main__':
    rospy.init_node('check_clients')
    rostest.rosrun('{name}', 'overlay_clients', Clients)
'''

PLUGIN_CPP = '''#include <gazebo/gazebo.hh>
namespace gazebo {{ class Hello : public WorldPlugin {{}}; }}
'''


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as out:
        out.write(text)


def simulation_package(src, name):
    """A Gazebo simulation package: world with model:// includes, a model folder exported
    through package.xml, a URDF robot, a launch file and a rostest using both clients."""
    root = os.path.join(src, name)
    write(os.path.join(root, 'package.xml'), PACKAGE_XML.format(name=name))
    write(os.path.join(root, 'CMakeLists.txt'), CMAKELISTS.format(name=name, extra=''))
    write(os.path.join(root, 'src', 'model_state_client.cpp'), CLIENT_CPP)
    write(os.path.join(root, 'models', 'overlay_crate', 'model.config'),
          MODEL_CONFIG.format(name='overlay_crate'))
    write(os.path.join(root, 'models', 'overlay_crate', 'model.sdf'), CRATE_SDF)
    write(os.path.join(root, 'worlds', 'crates.world'), WORLD)
    write(os.path.join(root, 'urdf', 'probe.urdf'), ROBOT_URDF)
    write(os.path.join(root, 'launch', 'probe_world.launch'), LAUNCH.format(name=name))
    write(os.path.join(root, 'test', 'clients.test'), TEST_LAUNCH.format(name=name))
    write(os.path.join(root, 'scripts', 'check_clients.py'), CHECK_CLIENTS.replace('{name}', name))
    os.chmod(os.path.join(root, 'scripts', 'check_clients.py'), 0o755)
    return root


def plugin_package(src, name):
    """A package that compiles a real Gazebo plugin next to its node."""
    root = os.path.join(src, name)
    write(os.path.join(root, 'package.xml'), PACKAGE_XML.format(name=name))
    write(os.path.join(root, 'CMakeLists.txt'), CMAKELISTS.format(
        name=name, extra='add_library(hello_plugin SHARED src/hello_plugin.cpp)\n'
                         'target_link_libraries(hello_plugin ${GAZEBO_LIBRARIES})'))
    write(os.path.join(root, 'src', 'model_state_client.cpp'), CLIENT_CPP)
    write(os.path.join(root, 'src', 'hello_plugin.cpp'), PLUGIN_CPP.format())
    return root
