#!/usr/bin/python3
"""Each shim of noetic_compat against a generated package that reproduces its failure.

Every case builds its package twice in a fresh overlay on this workspace: with the
workspace's environment as `source devel/setup.bash` leaves it (the shim on), and once more
with CMAKE_TOOLCHAIN_FILE unset (the shim off), where the build must stop with the error
the shim removes; so a case whose package no longer reproduces its failure fails too. A
failure that only Debian 13 has is checked to be absent on Debian 12.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shim_packages  # noqa: E402

SHIM_OFF = 'unset CMAKE_TOOLCHAIN_FILE && '


def catkin_finds_python_with_findpython():
    """Debian 13's catkin (0.8.10-17) finds its interpreter with CMake's FindPython, which
    takes Python_EXECUTABLE, not PYTHON_EXECUTABLE; Debian 12's (0.8.10-9) FindPythonInterp."""
    with open('/usr/share/catkin/cmake/python.cmake') as f:
        return 'find_package(Python ' in f.read()


def underlay_setup():
    """setup.bash of the devel (or install) space that holds noetic_compat."""
    for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(':'):
        if os.path.isdir(os.path.join(prefix, 'share', 'noetic_compat', 'cmake')):
            return os.path.join(prefix, 'setup.bash')
    raise RuntimeError('no space with share/noetic_compat/cmake in CMAKE_PREFIX_PATH')


def bash(script, path_first='/usr/bin:/bin'):
    env = dict(os.environ, PATH=path_first + ':' + os.environ.get('PATH', ''), LC_ALL='C')
    env.pop('CMAKE_TOOLCHAIN_FILE', None)
    return subprocess.run(['bash', '-c', script], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=300,
                          env=env)


class TestShims(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix='noetic_compat_')
        self.underlay = underlay_setup()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def build(self, make_package, name, shim_on, cmake_args='', path_first='/usr/bin:/bin'):
        ws = os.path.join(self.tmp, name)
        error = make_package(os.path.join(ws, 'src'))
        script = 'source %s && %scd %s && catkin_make -j1 %s' % (
            self.underlay, '' if shim_on else SHIM_OFF, ws, cmake_args)
        return error, bash(script, path_first), ws

    def check(self, make_package, error=None, **kwargs):
        package_error, off, _ = self.build(make_package, 'off', False, **kwargs)
        error = error or package_error
        self.assertNotEqual(off.returncode, 0, 'builds without the shim:\n' + off.stdout[-2000:])
        self.assertIn(error, off.stdout)
        _, on, ws = self.build(make_package, 'on', True, **kwargs)
        self.assertEqual(on.returncode, 0, on.stdout[-3000:])
        return ws

    def test_the_env_hook_hands_cmake_the_toolchain(self):
        hook = bash('source %s && echo "$CMAKE_TOOLCHAIN_FILE"' % self.underlay)
        toolchain = hook.stdout.strip()
        self.assertTrue(toolchain.endswith('/noetic_compat/cmake/noetic_compat_toolchain.cmake'))
        self.assertTrue(os.path.isfile(toolchain), toolchain)
        mine = bash('export CMAKE_TOOLCHAIN_FILE=/opt/mine.cmake && source %s && '
                    'echo "$CMAKE_TOOLCHAIN_FILE"' % self.underlay)
        self.assertEqual(mine.stdout.strip(), '/opt/mine.cmake')

    def test_noetic_header_names(self):
        ws = self.check(shim_packages.old_header_names)
        self.assertTrue(os.path.isfile(os.path.join(ws, 'devel', 'lib', 'libold_headers.so')))

    def check_builds_either_way(self, make_package):
        """For a failure this release does not have: the package builds with and without
        the shim."""
        for name, shim_on in (('off', False), ('on', True)):
            _, build, _ = self.build(make_package, name, shim_on)
            self.assertEqual(build.returncode, 0, build.stdout[-3000:])

    def test_boost_global_placeholders(self):
        ws = self.check(shim_packages.global_placeholders)
        run = subprocess.run([os.path.join(ws, 'devel', 'lib', 'bare_placeholders',
                                           'bare_placeholders')], timeout=30)
        self.assertEqual(run.returncode, 0)

    def test_libraries_needed_through_another_library(self):
        ws = self.check(shim_packages.indirect_library)
        run = subprocess.run([os.path.join(ws, 'devel', 'lib', 'indirect_library', 'replay'),
                              '--scan_topic', 'base_scan'], timeout=30)
        self.assertEqual(run.returncode, 0)

    def test_python3_of_debian_whatever_comes_first_in_path(self):
        venv = os.path.join(self.tmp, 'other_python')
        subprocess.run(['/usr/bin/python3', '-m', 'venv', '--without-pip', venv], check=True)
        ws = self.check(shim_packages.ament_angles, path_first=os.path.join(venv, 'bin'))
        with open(os.path.join(ws, 'build', 'CMakeCache.txt')) as f:
            cache = f.read()
        self.assertIn('PYTHON_EXECUTABLE:FILEPATH=/usr/bin/python3', cache)
        self.assertIn('Python_EXECUTABLE:FILEPATH=/usr/bin/python3', cache)

    def test_python3_for_find_python3_when_catkin_is_given_its_python(self):
        venv = os.path.join(self.tmp, 'other_python')
        subprocess.run(['/usr/bin/python3', '-m', 'venv', '--without-pip', venv], check=True)
        # Debian 13's catkin does not take -DPYTHON_EXECUTABLE and stops earlier.
        error = ("No module named 'catkin_pkg'" if catkin_finds_python_with_findpython()
                 else "No module named 'ament_package'")
        ws = self.check(shim_packages.ament_angles, path_first=os.path.join(venv, 'bin'),
                        cmake_args='-DPYTHON_EXECUTABLE=/usr/bin/python3', error=error)
        with open(os.path.join(ws, 'build', 'CMakeCache.txt')) as f:
            self.assertIn('Python3_EXECUTABLE:FILEPATH=/usr/bin/python3', f.read())


    def test_python_interp_found_by_a_second_package(self):
        if catkin_finds_python_with_findpython():
            self.check(shim_packages.python_interp_twice)
        else:
            self.check_builds_either_way(shim_packages.python_interp_twice)


if __name__ == '__main__':
    unittest.main()
