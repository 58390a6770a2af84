#!/usr/bin/python3
"""A user's workspace of packages written for Gazebo, built on top of this one.

The generated package is named turtlebot3_gazebo, like ours, so it must shadow it; its
CMakeLists calls find_package(gazebo) and catkin_package(DEPENDS gazebo) to build a plain
roscpp client of gazebo_msgs; its launch file includes gazebo_ros's empty_world.launch with
a world of model:// includes (a model folder exported in its package.xml) and spawns a
URDF robot with spawn_model. A second package that compiles a Gazebo plugin must stop at
configure time with one clear message.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'overlay'))
import overlay_workspace  # noqa: E402


def underlay_setup():
    """setup.bash of the devel space that provides find_package(gazebo)."""
    for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(':'):
        if os.path.isfile(os.path.join(prefix, 'share', 'gazebo', 'cmake', 'gazebo-config.cmake')):
            return os.path.join(prefix, 'setup.bash')
    raise RuntimeError('no devel space with share/gazebo/cmake in CMAKE_PREFIX_PATH')


def bash(script, timeout):
    env = dict(os.environ, PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''))
    return subprocess.run(['bash', '-c', script], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=timeout,
                          env=env)


CATKIN_MAKE = 'catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release'


class TestOverlay(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix='gazebo_overlay_')
        self.underlay = underlay_setup()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_gazebo_package_builds_shadows_and_runs(self):
        ws = os.path.join(self.tmp, 'user_ws')
        package = overlay_workspace.simulation_package(os.path.join(ws, 'src'),
                                                       'turtlebot3_gazebo')
        build = bash('source %s && cd %s && %s' % (self.underlay, ws, CATKIN_MAKE), 400)
        self.assertEqual(build.returncode, 0, build.stdout[-3000:])
        overlay = 'source %s/devel/setup.bash && ' % ws
        found = bash(overlay + 'rospack find turtlebot3_gazebo', 30)
        self.assertEqual(found.stdout.strip(), package)
        exports = bash(overlay + 'rospack plugins --attrib=gazebo_model_path gazebo_ros', 30)
        self.assertIn('turtlebot3_gazebo %s/models' % package, exports.stdout)
        run = bash(overlay + 'rostest turtlebot3_gazebo clients.test', 200)
        self.assertEqual(run.returncode, 0, run.stdout[-4000:])
        plain = re.sub(r'\x1b\[[0-9;]*m', '', run.stdout)  # rostest colours its summary
        self.assertIn('SUMMARY\n * RESULT: SUCCESS\n * TESTS: 1', plain)

    def test_a_gazebo_plugin_stops_the_configuration_with_one_message(self):
        ws = os.path.join(self.tmp, 'plugin_ws')
        overlay_workspace.plugin_package(os.path.join(ws, 'src'), 'hello_gazebo')
        build = bash('source %s && cd %s && %s' % (self.underlay, ws, CATKIN_MAKE), 400)
        self.assertNotEqual(build.returncode, 0)
        message = ' '.join(build.stdout.split())  # CMake wraps its messages
        self.assertIn("hello_gazebo: target 'hello_plugin' is a Gazebo plugin", message)
        self.assertIn('hello_plugin.cpp: #include <gazebo/gazebo.hh>', message)
        self.assertIn('Gazebo plugins cannot be built in this workspace', message)
        self.assertIn('libgazebo_ros_diff_drive.so', message)
        self.assertEqual(message.count('CMake Error'), 1)


if __name__ == '__main__':
    unittest.main()
