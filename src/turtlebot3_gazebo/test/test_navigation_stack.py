#!/usr/bin/python3
"""The navigation stack built from source on the round track; skipped, saying why, when
it is not built (the navigation packages are not Debian's: README, SLAM and navigation).

Runs navigation_integration.test (AMCL converging, move_base's 4 goals) and
slam_integration.test (gmapping's lap) with rostest, and prints their figures.
NAVIGATION_TEST_FIGURES names a folder to keep the figures and the saved map in.
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

ENV = dict(os.environ, PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''))


def missing(packages):
    return [p for p in packages if subprocess.run(
        ['rospack', 'find', p], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        env=ENV).returncode != 0]


class TestNavigationStack(unittest.TestCase):
    def setUp(self):
        self.folder = os.environ.get('NAVIGATION_TEST_FIGURES')
        if not self.folder:  # figures asked for are kept, others go with the test
            self.folder = tempfile.mkdtemp(prefix='navigation_figures_')
            self.addCleanup(shutil.rmtree, self.folder, ignore_errors=True)

    def run_rostest(self, test_file, packages):
        absent = missing(packages)
        if absent:
            self.skipTest('not built: %s (clone and build the navigation stack in an overlay: '
                          'src/turtlebot3_gazebo/README.md, SLAM and navigation)'
                          % ', '.join(absent))
        figures_file = os.path.join(self.folder, os.path.splitext(test_file)[0] + '.json')
        if os.path.exists(figures_file):
            os.remove(figures_file)
        result = subprocess.run(
            ['rostest', 'turtlebot3_gazebo', test_file, 'figures_file:=' + figures_file],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True,
            timeout=1000, env=ENV)
        figures = open(figures_file).read() if os.path.exists(figures_file) else None
        print('%s figures: %s' % (test_file, figures))
        self.assertEqual(result.returncode, 0, result.stdout[-4000:])
        # rostest also succeeds with no test run at all (the simulator gone before it began)
        self.assertIsNotNone(figures, 'no figures: the test node did not finish\n'
                             + result.stdout[-4000:])
        return json.loads(figures)

    def test_amcl_and_move_base(self):
        self.run_rostest('navigation_integration.test', ['amcl', 'map_server', 'move_base'])

    def test_gmapping_lap(self):
        self.run_rostest('slam_integration.test', ['gmapping', 'map_server'])


if __name__ == '__main__':
    unittest.main()
