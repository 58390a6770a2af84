"""After `source devel/setup.bash`, roslaunch does not import setuptools and setuptools still
imports (catkin_python_setup needs it). Where the standard library has distutils (Python
3.11, Debian 12), Python takes it from there rather than setuptools' copy, and a choice the
user made stays; where it has none (Python 3.12 and later, Debian 13), the variable is not
set, as it would make `import setuptools` fail."""
import os
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_roscd import SETUP  # noqa: E402 (run by its path, from any folder)

ENV = {'PATH': '/usr/bin:/bin', 'HOME': os.environ.get('HOME', '/')}
# What `import rosclean` (roslaunch imports it) leaves loaded.
PROBE = 'import sys, rosclean; print("setuptools" in sys.modules)'
DISTUTILS_PROBE = 'import distutils.spawn; print(distutils.__file__)'
STDLIB_PROBE = ('import os, sysconfig; '
                'print(os.path.isdir(os.path.join(sysconfig.get_path("stdlib"), "distutils")))')


def run_after_setup(probe, preset=None):
    """The variable's value after sourcing, then what `python3 -c probe` prints."""
    env = dict(ENV)
    if preset is not None:
        env['SETUPTOOLS_USE_DISTUTILS'] = preset
    script = f'source {SETUP} && echo "$SETUPTOOLS_USE_DISTUTILS" && python3 -c \'{probe}\''
    result = subprocess.run(['bash', '--norc', '--noprofile', '-c', script],
                            capture_output=True, text=True, timeout=30, env=env)
    return result


def stdlib_has_distutils():
    result = subprocess.run(['python3', '-c', STDLIB_PROBE], capture_output=True, text=True,
                            timeout=30, env=ENV, check=True)
    return result.stdout.strip() == 'True'


class PythonDistutilsTest(unittest.TestCase):
    def test_roslaunch_does_not_import_setuptools(self):
        result = run_after_setup(PROBE)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.splitlines()[-1], 'False')

    def test_setuptools_imports(self):
        result = run_after_setup('import setuptools')
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_distutils_comes_from_the_standard_library(self):
        if not stdlib_has_distutils():
            self.skipTest('the standard library has no distutils (Python 3.12 or later)')
        result = run_after_setup(DISTUTILS_PROBE)
        self.assertEqual(result.returncode, 0, result.stderr)
        value, distutils_file = result.stdout.split()
        self.assertEqual(value, 'stdlib')
        self.assertTrue(distutils_file.startswith('/usr/lib/python3'), distutils_file)
        self.assertNotIn('setuptools', distutils_file)

    def test_not_set_where_the_standard_library_has_no_distutils(self):
        if stdlib_has_distutils():
            self.skipTest('the standard library has distutils (Python 3.11)')
        result = run_after_setup('pass')
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout, '\n')

    def test_a_value_set_before_is_kept(self):
        result = run_after_setup('pass', preset='local')
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.split()[0], 'local')


if __name__ == '__main__':
    unittest.main()
