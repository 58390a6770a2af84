#!/usr/bin/python3
"""A user's clone of the TurtleBot3 repositories, built with catkin_make on top of this
workspace.

Packages named turtlebot3_bringup, turtlebot3_example and turtlebot3_fake that need
turtlebot3_msgs (find_package(catkin REQUIRED COMPONENTS ... turtlebot3_msgs), a C++
program including <turtlebot3_msgs/SensorState.h>, a Python script importing it, a message
of their own with a turtlebot3_msgs field) must build and run against ours. A
turtlebot3_msgs cloned into the user's workspace must shadow ours: rospack, Python and the
compiler all take the user's.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, 'overlay'))
import released_types  # noqa: E402
import user_workspace  # noqa: E402

# Plain catkin_make, as a user types it; bash() puts /usr/bin first in PATH (see README).
CATKIN_MAKE = 'catkin_make -j2'
# Wire size of a default message of each type, counted by hand from the released fields:
# SensorState = header (4 + 8 + 4) + 4 one-byte fields + 4 float32 + 2 int32;
# VersionInfo = three empty strings (4 bytes of length each); Sound = one uint8.
DEFAULT_SIZES = {'SensorState': 44, 'VersionInfo': 12, 'Sound': 1}


def underlay_setup():
    """setup.bash of the devel space that provides turtlebot3_msgs."""
    for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(':'):
        config = os.path.join(prefix, 'share', 'turtlebot3_msgs', 'cmake',
                              'turtlebot3_msgsConfig.cmake')
        if os.path.isfile(config) and os.path.isfile(os.path.join(prefix, 'setup.bash')):
            return prefix, os.path.join(prefix, 'setup.bash')
    raise RuntimeError('no devel space with turtlebot3_msgs in CMAKE_PREFIX_PATH')


def bash(script, timeout):
    env = dict(os.environ, PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''))
    return subprocess.run(['bash', '-c', script], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=timeout,
                          env=env)


def included_header(ws, package, header='turtlebot3_msgs/SensorState.h'):
    """The path of `header` that the compiler read for the package's program (from the
    dependency file gcc wrote beside the object)."""
    depfile = os.path.join(ws, 'build', package, 'CMakeFiles', package + '_report.dir',
                           'src', 'sensor_state_report.cpp.o.d')
    with open(depfile) as source:
        paths = source.read().replace('\\\n', ' ').split()
    found = [path for path in paths if path.endswith('/' + header)]
    if len(found) != 1:
        raise AssertionError('%s: %s listed %d times' % (depfile, header, len(found)))
    return os.path.realpath(found[0])


class TestOverlay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.table = released_types.read()
        cls.underlay_prefix, cls.underlay_setup = underlay_setup()

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix='turtlebot3_msgs_overlay_')

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def build(self, ws):
        build = bash('source %s && cd %s && %s' % (self.underlay_setup, ws, CATKIN_MAKE), 600)
        self.assertEqual(build.returncode, 0, build.stdout[-4000:])

    def in_overlay(self, ws, command):
        return bash('source %s/devel/setup.bash && %s' % (ws, command), 60)

    def assert_released_types(self, output):
        """output: 'turtlebot3_msgs/TYPE MD5 SIZE' lines of the C++ program."""
        expected = ['turtlebot3_msgs/%s %s %d' % (name, md5, DEFAULT_SIZES[name])
                    for name, md5 in self.table['md5']]
        self.assertEqual(sorted(output.split('\n')[:-1]), sorted(expected))

    def assert_programs_run(self, ws):
        """Both C++ programs and the Python script report the released types and say
        where turtlebot3_msgs' Python module was found."""
        for package in ('turtlebot3_bringup', 'turtlebot3_fake'):
            run = self.in_overlay(ws, 'rosrun %s sensor_state_report' % package)
            self.assertEqual(run.returncode, 0, run.stdout)
            self.assert_released_types(run.stdout)
        run = self.in_overlay(ws, 'rosrun turtlebot3_example sensor_state_report')
        self.assertEqual(run.returncode, 0, run.stdout)
        lines = run.stdout.split('\n')
        md5 = released_types.md5sums(self.table)
        self.assertEqual(sorted(lines[:3]), sorted('turtlebot3_msgs/%s %s' % item
                                                   for item in md5.items()))
        self.assertEqual(lines[3], 'SensorLog 1 0')
        self.assertTrue(lines[4].startswith('module '), run.stdout)
        return os.path.realpath(lines[4][len('module '):])

    def test_dependents_build_and_run_on_this_workspace(self):
        ws = os.path.join(self.tmp, 'training_ws')
        user_workspace.workspace(ws)
        self.build(ws)
        ours = os.path.dirname(HERE)
        found = self.in_overlay(ws, 'rospack find turtlebot3_msgs')
        self.assertEqual(os.path.realpath(found.stdout.strip()), os.path.realpath(ours))
        module = self.assert_programs_run(ws)
        underlay = os.path.realpath(self.underlay_prefix) + os.sep
        self.assertTrue(module.startswith(underlay), module)
        for package in ('turtlebot3_bringup', 'turtlebot3_fake'):
            self.assertTrue(included_header(ws, package).startswith(underlay), package)

    def test_a_cloned_turtlebot3_msgs_shadows_this_one(self):
        ws = os.path.join(self.tmp, 'clone_ws')
        folders = user_workspace.workspace(
            ws, with_msgs_types=released_types.definitions(self.table))
        self.build(ws)
        found = self.in_overlay(ws, 'rospack find turtlebot3_msgs')
        self.assertEqual(found.stdout.strip(), folders['turtlebot3_msgs'])
        module = self.assert_programs_run(ws)
        devel = os.path.realpath(os.path.join(ws, 'devel')) + os.sep
        self.assertTrue(module.startswith(devel), module)
        for package in ('turtlebot3_bringup', 'turtlebot3_fake'):
            self.assertTrue(included_header(ws, package).startswith(devel), package)


if __name__ == '__main__':
    unittest.main()
