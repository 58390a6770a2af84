#!/usr/bin/python3
"""The lines `make test` prints while its jobs run: a line per result file when the job that
wrote it ends (its counts and the job's own seconds), a line naming the running jobs when
nothing else was printed for a while, and at the end the ten slowest jobs."""
import os
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_summary import count_file  # noqa: E402

QUIET_S = 25.0  # a line at least every 30 s, with time to spare for polling and load


class Progress:
    def __init__(self, results_dir, out, clock=time.monotonic):
        self.results_dir, self.out, self.clock = results_dir, out, clock
        self.start = self.last_line = clock()
        self.reported = set()
        self.durations = []  # (seconds, job name)
        self.lock = threading.RLock()

    def stamp(self):
        total = self.clock() - self.start
        return '[%2d:%02d]' % (total // 60, total % 60)

    def write(self, text):
        with self.lock:
            self.out.write('%s %s\n' % (self.stamp(), text))
            self.out.flush()
            self.last_line = self.clock()

    def job_done(self, name, seconds, result_files, note=''):
        """A line per result file of a job that ended (a missing one is named); its
        seconds go into the slowest list."""
        with self.lock:
            self.durations.append((seconds, name))
            if note:
                self.write('FAIL %s: %s' % (name, note))
            for path in result_files:
                if os.path.exists(path):
                    self.file_line(path, seconds)
                else:
                    self.write('FAIL %s: no result file %s' % (name, self.relative(path)))

    def file_line(self, path, seconds):
        self.reported.add(os.path.abspath(path))
        counts = count_file(path)
        status = 'FAIL' if counts['failed'] else 'ok  '
        self.write('%s %s: %d passed, %d failed, %d skipped (%.0f s)' % (
            status, self.relative(path), counts['passed'], counts['failed'], counts['skipped'],
            seconds))

    def relative(self, path):
        return os.path.relpath(path, self.results_dir)

    def still_running(self, running):
        """Names the running jobs and their seconds so far when QUIET_S passed without a
        line. running: {job name: start time on this clock}."""
        with self.lock:
            now = self.clock()
            if now - self.last_line < QUIET_S or not running:
                return
            jobs = ', '.join('%s (%.0f s)' % (name, now - started)
                             for name, started in sorted(running.items(), key=lambda kv: kv[1]))
            self.write('running: ' + jobs)

    def unclaimed(self, paths):
        """A line for each result file no job named (found in the results folder at the
        end), so that every file the summary counts was shown."""
        with self.lock:
            for path in sorted(paths):
                if os.path.abspath(path) not in self.reported:
                    self.file_line(path, 0.0)

    def slowest(self, n=10):
        lines = ['slowest %d test jobs (seconds each took):' % n]
        for seconds, name in sorted(self.durations, reverse=True)[:n]:
            lines.append('  %6.0f s  %s' % (seconds, name))
        return '\n'.join(lines) + '\n'
