"""After `source devel/setup.bash`, roscd works as the tutorial types it."""
import os
import subprocess
import unittest

import rospkg

def devel_setup():
    """setup.bash of the devel space this test runs from (first catkin prefix)."""
    for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(os.pathsep):
        if os.path.isfile(os.path.join(prefix, '.catkin')):
            return os.path.join(prefix, 'setup.bash')
    raise RuntimeError('no catkin devel space on CMAKE_PREFIX_PATH: source devel/setup.bash')


SETUP = devel_setup()


class RoscdTest(unittest.TestCase):
    def test_roscd_enters_the_package_folder(self):
        script = f'source {SETUP} && roscd turtlebot3_description && cd urdf && pwd && ls'
        result = subprocess.run(['bash', '--norc', '--noprofile', '-c', script],
                                capture_output=True, text=True, timeout=30,
                                env={'PATH': '/usr/bin:/bin', 'HOME': os.environ.get('HOME', '/')})
        self.assertEqual(result.returncode, 0, result.stderr)
        folder, *files = result.stdout.split()
        self.assertEqual(folder, os.path.join(rospkg.RosPack().get_path('turtlebot3_description'),
                                              'urdf'))
        self.assertIn('turtlebot3_burger.urdf.xacro', files)


if __name__ == '__main__':
    unittest.main()
