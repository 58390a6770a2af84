"""display_xqrobot.launch with a URDF that has two roots ends promptly with
robot_state_publisher's parser message instead of showing a half robot."""
import os
import subprocess
import tempfile
import unittest

from mobility_testing.ports import free_port

TWO_ROOTS = """<?xml version="1.0"?>
<robot name="two_roots">
  <link name="chassis"/>
  <link name="loose_wheel"/>
</robot>
"""


class BadModelTest(unittest.TestCase):
    def test_two_roots_stop_the_launch_with_the_message(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, 'two_roots.urdf')
            with open(bad, 'w') as f:
                f.write(TWO_ROOTS)
            result = subprocess.run(
                ['roslaunch', '-p', str(free_port()), 'xqrobot_description',
                 'display_xqrobot.launch', f'model:={bad}'],
                capture_output=True, text=True, timeout=90, env=dict(os.environ, ROS_HOME=tmp))
        output = result.stdout + result.stderr
        self.assertIn('Two root links found: [chassis] and [loose_wheel]', output)
        self.assertIn('robot_state_publisher', output)


if __name__ == '__main__':
    unittest.main()
