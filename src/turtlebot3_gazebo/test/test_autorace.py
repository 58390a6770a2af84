#!/usr/bin/python3
"""ROBOTIS's AutoRace lane follower on the 2020 course, in the user's overlay; skipped,
saying what is missing, when the overlay is not built or not sourced (README, Autonomous
driving).

- lane following from the launch's spawn: the end of the first left turn within 90 s of
  sim time, never closer than 0.04 m to a line of the course texture, /detect/lane >= 5 Hz;
- the control: a constant forward command crosses the white line at the first corner.
AUTORACE_TEST_FIGURES names a folder to keep the figures in.
"""
import json
import os
import shutil
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'autorace'))
import run_autorace  # noqa: E402


class TestAutoRace(unittest.TestCase):
    def setUp(self):
        reason = run_autorace.missing()
        if reason:
            self.skipTest(reason)
        self.folder = os.environ.get('AUTORACE_TEST_FIGURES')
        if not self.folder:
            self.folder = tempfile.mkdtemp(prefix='autorace_figures_')
            self.addCleanup(shutil.rmtree, self.folder, ignore_errors=True)
        os.makedirs(self.folder, exist_ok=True)

    def run_mode(self, mode):
        figures_file = os.path.join(self.folder, mode + '.json')
        if os.path.exists(figures_file):
            os.remove(figures_file)
        logs = tempfile.mkdtemp(prefix='autorace_%s_logs_' % mode)  # kept if the run fails
        code, output = run_autorace.run_once(mode, figures_file, logs)
        figures = json.load(open(figures_file)) if os.path.exists(figures_file) else None
        if figures:
            print('%s figures: %s' % (mode, {k: v for k, v in figures.items() if k != 'trace'}))
        self.assertEqual(code, 0, 'launch output in %s\n%s' % (logs, output[-4000:]))
        self.assertIsNotNone(figures, 'no figures: the test did not finish\n' + output[-4000:])
        shutil.rmtree(logs, ignore_errors=True)

    def test_lane_following_through_the_first_left_turn(self):
        self.run_mode('lane')

    def test_control_straight_on_crosses_the_white_line(self):
        self.run_mode('control')


if __name__ == '__main__':
    unittest.main()
