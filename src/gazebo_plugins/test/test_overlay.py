#!/usr/bin/python3
"""A user's robot packages that depend on gazebo_plugins, built on top of this workspace.

The first package names gazebo_plugins alone (package.xml <depend>, find_package(catkin
COMPONENTS gazebo_plugins), catkin_package(CATKIN_DEPENDS gazebo_plugins)) and builds a
roscpp node that uses what Noetic's gazebo_plugins brings along: roscpp, tf, nav_msgs,
geometry_msgs, gazebo_msgs, linked with ${catkin_LIBRARIES} and
${gazebo_plugins_LIBRARIES}. The second depends on the first only and builds a node of the
same headers: gazebo_plugins' dependencies reach it through the first package's exports.
"""
import os
import shutil
import subprocess
import tempfile
import textwrap
import unittest

CATKIN_MAKE = 'catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release'

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>A robot package written for Gazebo.</description>
  <maintainer email="user@example.invalid">user</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>{depend}</depend>
</package>
'''

CMAKELISTS = '''cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS {depend})
catkin_package(CATKIN_DEPENDS {depend})
include_directories(${{catkin_INCLUDE_DIRS}} ${{{depend}_INCLUDE_DIRS}})
add_executable(${{PROJECT_NAME}}_check src/odom_check.cpp)
set_target_properties(${{PROJECT_NAME}}_check PROPERTIES OUTPUT_NAME odom_check)
target_link_libraries(${{PROJECT_NAME}}_check ${{catkin_LIBRARIES}} ${{{depend}_LIBRARIES}})
'''

# Prints the md5sums of the messages Gazebo's plugins publish, then looks up a transform
# in a tf::Transformer: compiled against roscpp, tf, nav_msgs, geometry_msgs and
# gazebo_msgs, linked with libtf and libroscpp's time; runs without a master.
NODE_CPP = r'''#include <cstdio>
#include <gazebo_msgs/ModelStates.h>
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf/tf.h>

int main() {
  ros::Time::init();
  tf::Transformer transformer;
  const ros::Time stamp(10.0);
  transformer.setTransform(tf::StampedTransform(
      tf::Transform(tf::createQuaternionFromYaw(0.5), tf::Vector3(1, 2, 0)), stamp, "odom",
      "base_footprint"));
  tf::StampedTransform found;
  transformer.lookupTransform("odom", "base_footprint", stamp, found);
  std::printf("%s %s %s %.3f %.3f\n", ros::message_traits::md5sum<nav_msgs::Odometry>(),
              ros::message_traits::md5sum<geometry_msgs::WrenchStamped>(),
              ros::message_traits::md5sum<gazebo_msgs::ModelStates>(),
              found.getOrigin().y(), tf::getYaw(found.getRotation()));
  return 0;
}
'''

# The md5sums of Noetic's messages (rosmsg md5 on any ROS 1 machine).
ODOMETRY_MD5 = 'cd5e73d190d741a2f92e81eda573aca7'
WRENCH_STAMPED_MD5 = 'd78d3cb249ce23087ade7e7d0c40cfa7'
MODEL_STATES_MD5 = '48c080191eb15c41858319b4d8a609c2'


def underlay_setup():
    """setup.bash of the devel space that holds gazebo_plugins."""
    for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(':'):
        if os.path.isfile(os.path.join(prefix, 'share', 'gazebo_plugins', 'cmake',
                                       'gazebo_pluginsConfig.cmake')):
            return os.path.join(prefix, 'setup.bash')
    raise RuntimeError('no devel space with gazebo_plugins in CMAKE_PREFIX_PATH')


def bash(script, timeout):
    env = dict(os.environ, PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''))
    return subprocess.run(['bash', '-c', script], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=timeout,
                          env=env)


def write_package(src, name, depend):
    folder = os.path.join(src, name)
    os.makedirs(os.path.join(folder, 'src'))
    files = {'package.xml': PACKAGE_XML, 'CMakeLists.txt': CMAKELISTS,
             'src/odom_check.cpp': NODE_CPP}
    for path, text in files.items():
        with open(os.path.join(folder, path), 'w') as f:
            f.write(text.format(name=name, depend=depend) if path != 'src/odom_check.cpp'
                    else text)


class TestGazeboPluginsDependency(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix='gazebo_plugins_overlay_')

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_packages_depending_on_gazebo_plugins_build_and_run(self):
        ws = os.path.join(self.tmp, 'user_ws')
        write_package(os.path.join(ws, 'src'), 'my_robot_gazebo', 'gazebo_plugins')
        write_package(os.path.join(ws, 'src'), 'my_robot_bringup', 'my_robot_gazebo')
        build = bash('source %s && cd %s && %s' % (underlay_setup(), ws, CATKIN_MAKE), 400)
        self.assertEqual(build.returncode, 0, build.stdout[-3000:])
        overlay = 'source %s/devel/setup.bash && ' % ws
        expected = '%s %s %s 2.000 0.500' % (ODOMETRY_MD5, WRENCH_STAMPED_MD5, MODEL_STATES_MD5)
        for package in ('my_robot_gazebo', 'my_robot_bringup'):
            run = bash(overlay + 'rosrun %s odom_check' % package, 30)
            self.assertEqual(run.returncode, 0, run.stdout)
            self.assertEqual(run.stdout.strip(), expected)
        depends = bash(overlay + 'rospack depends my_robot_bringup', 30)
        self.assertIn('gazebo_plugins', depends.stdout.split())


if __name__ == '__main__':
    unittest.main()
