"""`$(find xacro)/xacro.py`, the deprecated name of Melodic's xacro 1.13: the same output as
`xacro`, then Melodic's warning; on failure xacro's exit status without it."""
import os
import pty
import subprocess
import unittest
import xml.etree.ElementTree as ET

import rospkg
import yaml

PACKAGE = rospkg.RosPack().get_path('xacro')
XACRO = os.path.join(PACKAGE, 'xacro')
XACRO_PY = os.path.join(PACKAGE, 'xacro.py')
FIXTURE = os.path.join(PACKAGE, 'test', 'fixtures', 'two_links.urdf.xacro')
WARNING = 'xacro.py is deprecated; please use xacro instead'


def run(*command):
    return subprocess.run(command, capture_output=True, text=True, timeout=60)


def robot_summary(text):
    """(link names, cylinder (radius, length) per link, the joint's parent, child, z)."""
    robot = ET.fromstring(text)
    links = [link.get('name') for link in robot.findall('link')]
    cylinders = [(float(c.get('radius')), float(c.get('length')))
                 for c in robot.findall('link/visual/geometry/cylinder')]
    joint = robot.find('joint')
    z = float(joint.find('origin').get('xyz').split()[2])
    return links, cylinders, joint.find('parent').get('link'), joint.find('child').get('link'), z


class XacroPyTest(unittest.TestCase):
    def test_expands_the_file_as_xacro_does_and_then_warns_as_melodic_did(self):
        old = run(XACRO_PY, FIXTURE, 'length:=0.3')
        new = run(XACRO, FIXTURE, 'length:=0.3')
        self.assertEqual(old.returncode, 0, old.stderr)
        self.assertEqual(old.stdout, new.stdout)
        # Worked out from the fixture: two rods of radius 0.05 and the argument's length,
        # the hinge 2 * radius above the first.
        self.assertEqual(robot_summary(old.stdout),
                         (['first', 'second'], [(0.05, 0.3), (0.05, 0.3)], 'first', 'second', 0.1))
        # Not a terminal: xacro's warning() puts "warning: " before the text.
        self.assertEqual(old.stderr.splitlines()[-1], 'warning: ' + WARNING)
        self.assertNotIn('deprecated', new.stderr)

    def test_the_warning_is_yellow_on_a_terminal(self):
        controller, terminal = pty.openpty()
        try:
            result = subprocess.run([XACRO_PY, FIXTURE], stdout=subprocess.PIPE,
                                    stderr=terminal, timeout=60)
            os.close(terminal)
            terminal = None
            shown = os.read(controller, 4096).decode()
        finally:
            if terminal is not None:
                os.close(terminal)
            os.close(controller)
        self.assertEqual(result.returncode, 0)
        self.assertEqual(shown.strip(), '\033[93m%s\033[0m' % WARNING)

    def test_a_missing_file_fails_as_xacro_does_without_the_warning(self):
        result = run(XACRO_PY, '/nonexistent/robot.urdf.xacro')
        self.assertEqual(result.returncode, 2)
        self.assertIn('No such file or directory: /nonexistent/robot.urdf.xacro', result.stderr)
        self.assertNotIn('deprecated', result.stderr)

    def test_xacro_next_to_it_still_imports_the_xacro_module_not_this_file(self):
        # Python puts the script's folder first in sys.path, where xacro.py lies.
        result = run(XACRO, FIXTURE)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(robot_summary(result.stdout)[1], [(0.05, 0.2), (0.05, 0.2)])

    def test_a_launch_file_of_the_melodic_era_gets_its_robot_description(self):
        launch = os.path.join(PACKAGE, 'test', 'fixtures', 'xacro_py.launch')
        result = run('roslaunch', '--dump-params', launch)
        self.assertEqual(result.returncode, 0, result.stderr)
        description = yaml.safe_load(result.stdout)['/robot_description']
        self.assertEqual(robot_summary(description)[1], [(0.05, 0.5), (0.05, 0.5)])


if __name__ == '__main__':
    unittest.main()
