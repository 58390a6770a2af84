#!/usr/bin/python3
"""Watches a test-results folder while the tests run: a line per result file once it is
final (its counts, and the time since the previous one: about the test's own run time),
and at the end the ten slowest. Stops when the file named by --stop exists
(the test run writes it when done)."""
import argparse
import glob
import os
import sys
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_summary import count_file  # noqa: E402


class Watcher:
    def __init__(self, results_dir, out, clock=time.monotonic, wall_clock=time.time):
        self.results_dir, self.out, self.clock, self.wall_clock = results_dir, out, clock, wall_clock
        self.start = self.last = clock()
        self.seen = set()
        self.durations = []  # (seconds, name)

    def poll(self, final=False):
        """Prints the result files that are done: while the tests run, every complete one but
        the newest (rostest creates its files empty when a test starts and writes them when
        it ends; tests run one at a time, so a file is final once a newer one exists), and
        all of them on the final poll."""
        paths = glob.glob(os.path.join(self.results_dir, '**', '*.xml'), recursive=True)
        stamped = []
        for path in paths:
            try:
                stamped.append((os.path.getmtime(path), path))
            except OSError:
                continue
        stamped.sort()
        done = stamped if final else stamped[:-1]
        for _, path in done:
            if path in self.seen or not (final or (self.settled(path) and self.complete(path))):
                continue
            self.seen.add(path)
            now = self.clock()
            name = os.path.relpath(path, self.results_dir)
            counts = count_file(path)
            seconds = now - self.last
            self.last = now
            self.durations.append((seconds, name))
            total = now - self.start
            status = 'FAIL' if counts['failed'] else 'ok  '
            self.out.write('[%2d:%02d] %s %s: %d passed, %d failed, %d skipped (%.0f s)\n' % (
                total // 60, total % 60, status, name, counts['passed'], counts['failed'],
                counts['skipped'], seconds))
            self.out.flush()

    @staticmethod
    def complete(path):
        """rostest creates its result files empty when a test starts and writes them when it
        ends: an empty or unparsable file is not done yet."""
        try:
            ET.parse(path)
            return True
        except (ET.ParseError, OSError):
            return False

    def settled(self, path):
        try:
            return self.wall_clock() - os.path.getmtime(path) >= 1.0
        except OSError:
            return False

    def slowest(self, n=10):
        lines = ['slowest %d result files (seconds since the one before):' % n]
        for seconds, name in sorted(self.durations, reverse=True)[:n]:
            lines.append('  %6.0f s  %s' % (seconds, name))
        return '\n'.join(lines) + '\n'


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('results_dir')
    parser.add_argument('--stop', required=True, help='stop once this file exists')
    parser.add_argument('--period', type=float, default=2.0)
    args = parser.parse_args()
    watcher = Watcher(args.results_dir, sys.stdout)
    while not os.path.exists(args.stop):
        watcher.poll()
        time.sleep(args.period)
    watcher.poll(final=True)
    sys.stdout.write(watcher.slowest())


if __name__ == '__main__':
    main()
