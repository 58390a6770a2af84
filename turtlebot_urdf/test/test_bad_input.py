"""model.launch with a broken xacro ends at once with xacro's own message."""
import os
import subprocess
import tempfile
import unittest

from mobility_testing.ports import free_port

XACRO = subprocess.run(['rospack', 'find', 'turtlebot3_description'], capture_output=True,
                       text=True, check=True).stdout.strip() + '/urdf/turtlebot3_burger.urdf.xacro'


class BadModelTest(unittest.TestCase):
    def test_typo_in_xacro_stops_the_launch_with_the_message(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, 'typo.urdf.xacro')
            with open(XACRO) as f, open(bad, 'w') as out:
                out.write(f.read().replace('<link name="base_footprint"/>',
                                           '<link name="base_footprint">', 1))
            env = dict(os.environ, ROS_HOME=tmp)
            result = subprocess.run(
                ['roslaunch', '-p', str(free_port()), 'turtlebot_urdf', 'model.launch',
                 f'model:={bad}', 'gui:=false'],
                capture_output=True, text=True, timeout=60, env=env)
        output = result.stdout + result.stderr
        self.assertNotEqual(result.returncode, 0, output)
        self.assertIn('mismatched tag', output)
        self.assertIn('Cannot load command parameter [robot_description]', output)


if __name__ == '__main__':
    unittest.main()
