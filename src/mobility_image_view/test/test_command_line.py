"""The viewer's script refuses to start without a master, with a clear message."""
import os
import subprocess
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts',
                      'image_view_gui')


class CommandLineTest(unittest.TestCase):
    def test_no_master_is_a_clear_error(self):
        env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:9/')
        result = subprocess.run([SCRIPT, '/camera/image_raw'], env=env, capture_output=True,
                                text=True, timeout=30)
        self.assertEqual(result.returncode, 1)
        self.assertEqual(result.stderr.strip(), 'image_view_gui: no ROS master at '
                         'http://127.0.0.1:9/: start roscore first')


if __name__ == '__main__':
    unittest.main()
