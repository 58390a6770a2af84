#!/usr/bin/python3
"""Runs the workspace's test jobs (test_jobs.py) on a few workers at once, each worker with
its own Xvfb server and ROS_HOME (every rostest starts its own master on a free port).
Longest jobs start first; jobs of one group (test_jobs.GROUPS) never overlap. A job that
outlives its time limit is killed with everything it started and its result file says so.
Prints a line per result file as its job ends (test_progress.py); each job's output goes
to a log of its own and, as it ends, to one log of the whole run."""
import argparse
import os
import re
import signal
import subprocess
import sys
import threading
import time
from xml.sax.saxutils import quoteattr

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_jobs  # noqa: E402
from test_progress import Progress  # noqa: E402
from xvfb_display import Display  # noqa: E402

KILL_GRACE_S = 10.0


class Scheduler:
    """Hands out jobs in order; a job waits while another of its group runs."""

    def __init__(self, jobs, clock=time.monotonic):
        self.pending = list(jobs)
        self.running = {}  # name -> (start, group)
        self.clock = clock
        self.changed = threading.Condition()

    def take(self):
        """The next job that may start now, waiting for one; None when none is left."""
        with self.changed:
            while True:
                busy = {group for _, group in self.running.values() if group}
                for job in self.pending:
                    if job.group is None or job.group not in busy:
                        self.pending.remove(job)
                        self.running[job.name] = (self.clock(), job.group)
                        return job
                if not self.pending:
                    return None
                self.changed.wait()

    def done(self, job):
        with self.changed:
            del self.running[job.name]
            self.changed.notify_all()

    def running_since(self):
        with self.changed:
            return {name: start for name, (start, _) in self.running.items()}


def failure_xml(name, message):
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<testsuite name=%s tests="1" failures="1" errors="0">\n'
            '  <testcase classname="test_runner" name=%s>\n'
            '    <failure message=%s/>\n  </testcase>\n</testsuite>\n'
            % (quoteattr(name), quoteattr(name), quoteattr(message)))


def write_failure(path, name, message):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write(failure_xml(name, message))


def kill_group(process):
    """Ends the job's process group (rostest, its master and nodes, GUI programs)."""
    for sig, grace in ((signal.SIGTERM, KILL_GRACE_S), (signal.SIGKILL, None)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        if grace is not None:
            try:
                process.wait(timeout=grace)
            except subprocess.TimeoutExpired:
                pass


class Runner:
    def __init__(self, jobs, workers, build_dir, progress, log_path, display=Display):
        self.scheduler = Scheduler(jobs)
        self.display = display
        self.workers = workers
        self.build_dir = build_dir
        self.progress = progress
        self.log_path = log_path
        self.log_lock = threading.Lock()
        self.durations = {}
        self.errors = []
        self.log_dir = os.path.join(build_dir, 'test_output')
        self.started = {}  # job name -> its process, while it runs
        self.displays = []

    def run(self):
        os.makedirs(self.log_dir, exist_ok=True)
        open(self.log_path, 'w').close()
        threads = [threading.Thread(target=self.worker, args=(i,), daemon=True)
                   for i in range(self.workers)]
        for thread in threads:
            thread.start()
        while any(thread.is_alive() for thread in threads):
            self.progress.still_running(self.scheduler.running_since())
            for thread in threads:
                thread.join(timeout=1.0)
        return not self.errors

    def worker(self, index):
        display = self.display(os.path.join(self.log_dir, f'xvfb-worker{index}.log'))
        self.displays.append(display)
        try:
            env = self.worker_env(index, display.start())
            while True:
                job = self.scheduler.take()
                if job is None:
                    return
                try:
                    self.run_job(job, env)
                finally:
                    self.scheduler.done(job)
        except Exception as err:  # noqa: BLE001 - reported, and the run then fails
            self.errors.append(f'worker {index}: {err}')
            self.progress.write(f'FAIL worker {index} stopped: {err}')
            self.drain()
        finally:
            display.stop()

    def drain(self):
        """After a worker's failure, the jobs left are failures of their own, not silence."""
        while True:
            job = self.scheduler.take()
            if job is None:
                return
            write_failure(job.result_files[0], job.name, 'not run: a test worker failed')
            self.progress.job_done(job.name, 0.0, job.result_files[:1])
            self.scheduler.done(job)

    def worker_env(self, index, display):
        ros_home = os.path.join(self.build_dir, 'ros_home', f'worker{index}')
        os.makedirs(ros_home, exist_ok=True)
        return dict(os.environ, DISPLAY=display, ROS_HOME=ros_home,
                    ROS_LOG_DIR=os.path.join(ros_home, 'log'))

    def run_job(self, job, env):
        log = os.path.join(self.log_dir, job.name + '.log')
        start = time.monotonic()
        with open(log, 'w') as out:
            process = subprocess.Popen(job.command, cwd=job.cwd, env=env,
                                       stdout=out, stderr=subprocess.STDOUT,
                                       stdin=subprocess.DEVNULL, start_new_session=True)
            self.started[job.name] = process
            try:
                status = process.wait(timeout=job.limit_s)
                note = ''
            except subprocess.TimeoutExpired:
                status = None
                note = f'killed after {job.limit_s:.0f} s (its time limit)'
            kill_group(process)
            process.wait()
            del self.started[job.name]
        seconds = time.monotonic() - start
        self.durations[job.name] = seconds
        if note:
            write_failure(job.result_files[0], job.name, note)
        elif not os.path.exists(job.result_files[0]):
            write_failure(job.result_files[0], job.name, f'exited {status} without a result file')
        self.append_log(job, log, f'exit {status}, {seconds:.0f} s on {env["DISPLAY"]}')
        self.progress.job_done(job.name, seconds, job.result_files, note)

    def abort(self, signum, _frame):
        """On SIGTERM or SIGINT: ends every running job (each in a session of its own, out of
        the reach of a terminal's Ctrl-C) and every X server, then the run."""
        for process in list(self.started.values()):
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        for display in self.displays:
            display.stop()
        raise SystemExit(128 + signum)

    def append_log(self, job, log, how):
        with self.log_lock, open(self.log_path, 'a') as out, open(log, errors='replace') as part:
            out.write(f'==== {job.name}: {how} ====\n')
            out.write(part.read())


def result_files(results_dir):
    found = []
    for folder, _, names in os.walk(results_dir):
        found += [os.path.join(folder, n) for n in names if n.endswith('.xml')]
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('build_dir')
    parser.add_argument('--jobs', type=int, default=2, help='workers (default 2)')
    parser.add_argument('--log', required=True, help='the whole run\'s output')
    parser.add_argument('--repo', required=True, help='the source root (for the pytest job)')
    parser.add_argument('--only', default='',
                        help='run only the jobs whose name this regular expression finds')
    args = parser.parse_args()
    build_dir = os.path.abspath(args.build_dir)
    results_dir = os.path.join(build_dir, 'test_results')
    durations_path = os.path.join(build_dir, 'test_durations.json')
    jobs = [test_jobs.job_from_ctest(entry) for entry in test_jobs.ctest_entries(build_dir)]
    jobs.append(test_jobs.pytest_job(os.path.abspath(args.repo), results_dir))
    jobs = [job for job in jobs if re.search(args.only, job.name)]
    durations = test_jobs.load_durations(durations_path)
    jobs = test_jobs.longest_first(jobs, durations)
    progress = Progress(results_dir, sys.stdout)
    progress.write(f'{len(jobs)} test jobs on {args.jobs} workers')
    runner = Runner(jobs, args.jobs, build_dir, progress, args.log)
    signal.signal(signal.SIGTERM, runner.abort)
    signal.signal(signal.SIGINT, runner.abort)
    ok = runner.run()
    progress.unclaimed(result_files(results_dir))
    sys.stdout.write(progress.slowest())
    test_jobs.save_durations(durations_path, dict(durations, **runner.durations))
    for error in runner.errors:
        print('test runner:', error)
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
