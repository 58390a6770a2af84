"""Writes a catkin workspace as a user's clone of the TurtleBot3 repositories looks to
catkin: turtlebot3_bringup, turtlebot3_example and turtlebot3_fake depending on
turtlebot3_msgs, optionally with a turtlebot3_msgs of its own, to be built with catkin_make
on top of this workspace."""
import os

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>A package of a user's workspace that uses turtlebot3_msgs.</description>
  <maintainer email="user@example.invalid">user</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>catkin</buildtool_depend>
{depends}
</package>
'''

MESSAGE_DEPENDS = '''
  <build_depend>message_generation</build_depend>
  <exec_depend>message_runtime</exec_depend>'''

# A C++ program (target PACKAGE_report, program sensor_state_report) that includes the
# generated headers and prints, for each type, its name, md5sum and the wire size of a
# default message. It makes no NodeHandle: no master needed.
REPORT_CPP = r'''#include <cstdio>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <turtlebot3_msgs/SensorState.h>
#include <turtlebot3_msgs/Sound.h>
#include <turtlebot3_msgs/VersionInfo.h>

template <class M>
void report() {
  M message;
  std::printf("%s %s %u\n", ros::message_traits::DataType<M>::value(),
              ros::message_traits::MD5Sum<M>::value(),
              ros::serialization::serializationLength(message));
}

int main() {
  report<turtlebot3_msgs::SensorState>();
  report<turtlebot3_msgs::VersionInfo>();
  report<turtlebot3_msgs::Sound>();
  return 0;
}
'''

CPP_CMAKELISTS = '''cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS {components} turtlebot3_msgs)
catkin_package(CATKIN_DEPENDS {components} turtlebot3_msgs)
include_directories(${{catkin_INCLUDE_DIRS}})
add_executable({name}_report src/sensor_state_report.cpp)
set_target_properties({name}_report PROPERTIES OUTPUT_NAME sensor_state_report)
add_dependencies({name}_report ${{catkin_EXPORTED_TARGETS}})
target_link_libraries({name}_report ${{catkin_LIBRARIES}})
'''

# The Python side: a message of the package's own with a turtlebot3_msgs field, and a
# script that imports both and prints what it found.
PYTHON_CMAKELISTS = '''cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS rospy std_msgs turtlebot3_msgs message_generation)
add_message_files(FILES SensorLog.msg)
generate_messages(DEPENDENCIES std_msgs turtlebot3_msgs)
catkin_package(CATKIN_DEPENDS rospy std_msgs turtlebot3_msgs message_runtime)
catkin_install_python(PROGRAMS nodes/sensor_state_report
  DESTINATION ${{CATKIN_PACKAGE_BIN_DESTINATION}})
'''

SENSOR_LOG_MSG = '''Header header
turtlebot3_msgs/SensorState[] states
turtlebot3_msgs/Sound last_sound
'''

REPORT_PY = '''#!/usr/bin/python3
import turtlebot3_msgs.msg
from turtlebot3_msgs.msg import SensorState, Sound, VersionInfo
from {name}.msg import SensorLog

for cls in (SensorState, VersionInfo, Sound):
    print(cls._type, cls._md5sum)
log = SensorLog(states=[SensorState(bumper=SensorState.BUMPER_FORWARD)])
print('SensorLog', log.states[0].bumper, log.last_sound.value)
print('module', turtlebot3_msgs.msg.__file__)
'''

# The messages package, its .msg files written from (name, type) fields and
# (name, value) uint8 constants.
MSGS_CMAKELISTS = '''cmake_minimum_required(VERSION 3.0.2)
project(turtlebot3_msgs)
find_package(catkin REQUIRED COMPONENTS std_msgs message_generation)
add_message_files(FILES {files})
generate_messages(DEPENDENCIES std_msgs)
catkin_package(CATKIN_DEPENDS std_msgs message_runtime)
'''

# Package -> (its catkin components, True for the C++ program, False for the Python one).
DEPENDENTS = {
    'turtlebot3_bringup': ('roscpp std_msgs sensor_msgs diagnostic_msgs', True),
    'turtlebot3_example': ('rospy std_msgs', False),
    'turtlebot3_fake': ('roscpp std_msgs sensor_msgs geometry_msgs nav_msgs tf', True),
}


def write(path, text, executable=False):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as out:
        out.write(text)
    if executable:
        os.chmod(path, 0o755)


def depends(names):
    return '\n'.join('  <depend>%s</depend>' % name for name in names)


def dependent_package(src, name):
    """One of the TurtleBot3 packages that need turtlebot3_msgs, as catkin sees it."""
    components, is_cpp = DEPENDENTS[name]
    root = os.path.join(src, name)
    names = components.split() + ['turtlebot3_msgs']
    if is_cpp:
        write(os.path.join(root, 'package.xml'),
              PACKAGE_XML.format(name=name, depends=depends(names)))
        write(os.path.join(root, 'CMakeLists.txt'),
              CPP_CMAKELISTS.format(name=name, components=components))
        write(os.path.join(root, 'src', 'sensor_state_report.cpp'), REPORT_CPP)
    else:
        write(os.path.join(root, 'package.xml'),
              PACKAGE_XML.format(name=name, depends=depends(names) + MESSAGE_DEPENDS))
        write(os.path.join(root, 'CMakeLists.txt'), PYTHON_CMAKELISTS.format(name=name))
        write(os.path.join(root, 'msg', 'SensorLog.msg'), SENSOR_LOG_MSG)
        write(os.path.join(root, 'nodes', 'sensor_state_report'), REPORT_PY.format(name=name),
              executable=True)
    return root


def msgs_package(src, types):
    """A turtlebot3_msgs of the user's own; types: {name: (fields, constants)}."""
    root = os.path.join(src, 'turtlebot3_msgs')
    write(os.path.join(root, 'package.xml'), PACKAGE_XML.format(
        name='turtlebot3_msgs', depends=depends(['std_msgs']) + MESSAGE_DEPENDS))
    files = ' '.join(name + '.msg' for name in types)
    write(os.path.join(root, 'CMakeLists.txt'), MSGS_CMAKELISTS.format(files=files))
    for name, (fields, constants) in types.items():
        lines = ['uint8 %s = %s' % constant for constant in constants]
        lines += ['%s %s' % (kind, field) for field, kind in fields]
        write(os.path.join(root, 'msg', name + '.msg'), '\n'.join(lines) + '\n')
    return root


def workspace(root, with_msgs_types=None):
    """The three dependents under root/src, plus a turtlebot3_msgs when types are given.
    Returns {package name: its source folder}."""
    src = os.path.join(root, 'src')
    folders = {name: dependent_package(src, name) for name in DEPENDENTS}
    if with_msgs_types is not None:
        folders['turtlebot3_msgs'] = msgs_package(src, with_msgs_types)
    return folders
