"""After `source devel/setup.bash`, Python takes distutils from the standard library, so
roslaunch does not import setuptools; a choice the user made stays."""
import os
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_roscd import SETUP  # noqa: E402 (run by its path, from any folder)

# What `import rosclean` (roslaunch imports it) leaves loaded.
PROBE = ('import sys, distutils.spawn, rosclean; '
         'print(distutils.__file__); print("setuptools" in sys.modules)')


def run_after_setup(preset=None):
    env = {'PATH': '/usr/bin:/bin', 'HOME': os.environ.get('HOME', '/')}
    if preset is not None:
        env['SETUPTOOLS_USE_DISTUTILS'] = preset
    script = f'source {SETUP} && echo "$SETUPTOOLS_USE_DISTUTILS" && python3 -c \'{PROBE}\''
    result = subprocess.run(['bash', '--norc', '--noprofile', '-c', script],
                            capture_output=True, text=True, timeout=30, env=env)
    return result


class PythonDistutilsTest(unittest.TestCase):
    def test_distutils_comes_from_the_standard_library(self):
        result = run_after_setup()
        self.assertEqual(result.returncode, 0, result.stderr)
        value, distutils_file, setuptools_loaded = result.stdout.split()
        self.assertEqual(value, 'stdlib')
        self.assertTrue(distutils_file.startswith('/usr/lib/python3'), distutils_file)
        self.assertNotIn('setuptools', distutils_file)
        self.assertEqual(setuptools_loaded, 'False')

    def test_a_value_set_before_is_kept(self):
        result = run_after_setup('local')
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.split()[0], 'local')


if __name__ == '__main__':
    unittest.main()
