"""make test's runner (test_jobs.py, test_runner.py, test_progress.py) on made-up ctest
entries and jobs that are small shell commands; no ROS, no X server."""
import io
import os
import subprocess
import sys
import threading
import time

import pytest

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import test_jobs  # noqa: E402
import test_runner  # noqa: E402
from test_progress import Progress  # noqa: E402
from test_summary import count_file  # noqa: E402
from hand_clock import Clock  # noqa: E402

PASSING = '<testsuite><testcase classname="c" name="a"/><testcase classname="c" name="b"/></testsuite>'


def ctest_entry(name, result, *commands):
    return {'name': name, 'command': ['/b/env_cached.sh', '/usr/bin/python3', '/c/run_tests.py',
                                      result, '--return-code', *commands],
            'properties': [{'name': 'WORKING_DIRECTORY', 'value': '/b/src/pkg'}]}


def test_a_gtest_entry_is_one_job_with_its_result_file_and_the_default_limit():
    job = test_jobs.job_from_ctest(ctest_entry(
        '_ctest_sim_render_gtest_sim_render_tests', '/b/test_results/sim_render/gtest-x.xml',
        '/b/devel/lib/sim_render/sim_render_tests --gtest_output=xml:/b/x.xml'))
    assert (job.name, job.package, job.kind, job.cwd) == (
        'sim_render_gtest_sim_render_tests', 'sim_render', 'gtest', '/b/src/pkg')
    assert job.result_files == ['/b/test_results/sim_render/gtest-x.xml']
    assert job.limit_s == test_jobs.DEFAULT_LIMIT_S


def test_a_rostest_names_a_result_file_per_test_and_sums_their_time_limits(tmp_path):
    folder = str(tmp_path)
    launch = os.path.join(folder, 'two.test')
    with open(launch, 'w') as f:
        f.write('<launch><test test-name="first" pkg="p" type="a" time-limit="90"/>'
                '<group><test test-name="second" pkg="p" type="b"/></group></launch>')
    job = test_jobs.job_from_ctest(ctest_entry(
        '_ctest_p_rostest_test_two.test', '/b/test_results/p/rostest-test_two.xml',
        '/usr/bin/python3 /usr/bin/rostest --package=p --results-filename test_two.xml ' + launch))
    assert job.result_files == ['/b/test_results/p/rostest-test_two.xml',
                                '/b/test_results/p/rosunit-first.xml',
                                '/b/test_results/p/rosunit-second.xml']
    assert job.limit_s == 90 + 60 + test_jobs.ROSTEST_MARGIN_S  # rostest's default is 60 s


def test_an_entry_that_is_not_catkins_says_which():
    with pytest.raises(test_jobs.JobListError, match="_ctest_p_gtest_x: no '--return-code'"):
        test_jobs.job_from_ctest({'name': '_ctest_p_gtest_x', 'command': ['/bin/true']})
    with pytest.raises(test_jobs.JobListError, match='not in a folder named after its package'):
        test_jobs.job_from_ctest(ctest_entry('_ctest_p_gtest_x', '/b/test_results/q/x.xml', 'x'))


def job(name, kind='gtest', group=None):
    return test_jobs.Job(name=name, package='p', kind=kind, command=[], cwd=None,
                         result_files=[], group=group)


def test_jobs_start_longest_first_by_the_last_run_and_by_kind_when_never_measured():
    jobs = [job('short', 'gtest'), job('new_rostest', 'rostest'), job('long', 'gtest'),
            job('new_gtest', 'gtest')]
    ordered = test_jobs.longest_first(jobs, {'short': 1.0, 'long': 300.0})
    assert [j.name for j in ordered] == ['long', 'new_rostest', 'new_gtest', 'short']


def test_durations_round_trip_and_a_bad_file_is_no_history(tmp_path):
    path = os.path.join(str(tmp_path), 'd.json')
    assert test_jobs.load_durations(path) == {}
    test_jobs.save_durations(path, {'a': 2.5})
    assert test_jobs.load_durations(path) == {'a': 2.5}
    with open(path, 'w') as f:
        f.write('[not a dict')
    assert test_jobs.load_durations(path) == {}


def test_a_job_waits_while_one_of_its_group_runs_and_others_go_ahead():
    scheduler = test_runner.Scheduler([job('rviz_a', group='rviz'), job('rviz_b', group='rviz'),
                                       job('plain')])
    first = scheduler.take()
    assert first.name == 'rviz_a'
    assert scheduler.take().name == 'plain'  # rviz_b must wait for rviz_a
    taken = []
    waiter = threading.Thread(target=lambda: taken.append(scheduler.take()))
    waiter.start()
    waiter.join(timeout=0.2)
    assert waiter.is_alive() and not taken
    scheduler.done(first)
    waiter.join(timeout=5)
    assert taken[0].name == 'rviz_b'
    assert scheduler.take() is None


class FakeDisplay:
    def __init__(self, log_path=None):
        pass

    def start(self):
        return ':none'

    def stop(self):
        pass


def shell_job(name, script, folder, limit_s=30.0):
    result = os.path.join(folder, 'results', 'p', name + '.xml')
    return test_jobs.Job(name=name, package='p', kind='gtest', cwd=folder, limit_s=limit_s,
                         command=['/bin/sh', '-c', script.replace('RESULT', result)],
                         result_files=[result])


def run_jobs(folder, jobs, workers=2):
    out = io.StringIO()
    progress = Progress(os.path.join(folder, 'results'), out)
    runner = test_runner.Runner(jobs, workers, folder, progress, os.path.join(folder, 'all.log'),
                                display=FakeDisplay)
    assert runner.run()
    return out.getvalue(), runner


def test_passing_jobs_report_their_files_and_their_output_lands_in_the_log(tmp_path):
    folder = str(tmp_path)
    script = "mkdir -p $(dirname RESULT); echo 'hello from' $DISPLAY; echo '%s' > RESULT" % PASSING
    lines, runner = run_jobs(folder, [shell_job('a', script, folder), shell_job('b', script, folder)])
    assert 'ok   p/a.xml: 2 passed, 0 failed, 0 skipped' in lines
    assert 'ok   p/b.xml: 2 passed, 0 failed, 0 skipped' in lines
    with open(os.path.join(folder, 'all.log')) as f:
        log = f.read()
    assert log.count('hello from :none') == 2 and '==== a: exit 0, 0 s on :none ====' in log
    assert set(runner.durations) == {'a', 'b'}
    assert os.path.isdir(os.path.join(folder, 'ros_home', 'worker1'))


def test_a_job_over_its_limit_is_killed_with_its_children_and_counts_as_failed(tmp_path):
    folder = str(tmp_path)
    pid_file = os.path.join(folder, 'child.pid')
    # A placeholder result as rostest leaves one, then a child that would outlive the job.
    script = ("mkdir -p $(dirname RESULT); echo '%s' > RESULT; sleep 300 & echo $! > %s; wait"
              % (PASSING, pid_file))
    start = time.monotonic()
    lines, _ = run_jobs(folder, [shell_job('hangs', script, folder, limit_s=1.0)], workers=1)
    assert time.monotonic() - start < 20
    assert 'FAIL hangs: killed after 1 s (its time limit)' in lines
    result = os.path.join(folder, 'results', 'p', 'hangs.xml')
    assert count_file(result) == {'passed': 0, 'failed': 1, 'skipped': 0}
    with open(pid_file) as f:
        child = int(f.read())
    gone_by = time.monotonic() + 5  # a killed process takes a moment to exit
    while running(child) and time.monotonic() < gone_by:
        time.sleep(0.01)
    assert not running(child)


def running(pid):
    """False for a process that is gone or dead but not yet reaped (a zombie)."""
    try:
        with open('/proc/%d/stat' % pid) as f:
            return f.read().rsplit(')', 1)[1].split()[0] != 'Z'
    except FileNotFoundError:
        return False


def test_a_job_that_leaves_no_result_file_counts_as_failed(tmp_path):
    folder = str(tmp_path)
    lines, _ = run_jobs(folder, [shell_job('silent', 'exit 3', folder)], workers=1)
    result = os.path.join(folder, 'results', 'p', 'silent.xml')
    assert count_file(result) == {'passed': 0, 'failed': 1, 'skipped': 0}
    assert 'FAIL p/silent.xml: 0 passed, 1 failed' in lines


def test_running_jobs_are_named_after_25_quiet_seconds():
    clock, out = Clock(), io.StringIO()
    progress = Progress('/r', out, clock)
    clock.now = 24
    progress.still_running({'slow_rostest': 0.0})
    assert out.getvalue() == ''
    clock.now = 26
    progress.still_running({'slow_rostest': 0.0, 'gtest': 20.0})
    progress.still_running({'slow_rostest': 0.0})
    assert out.getvalue().splitlines() == ['[ 0:26] running: slow_rostest (26 s), gtest (6 s)']


def test_a_line_per_file_of_an_ended_job_a_missing_one_named_and_the_slowest_at_the_end(tmp_path):
    folder = str(tmp_path)
    clock, out = Clock(), io.StringIO()
    progress = Progress(folder, out, clock)
    present = os.path.join(folder, 'p', 'rostest-t.xml')
    os.makedirs(os.path.dirname(present))
    with open(present, 'w') as f:
        f.write(PASSING)
    clock.now = 75
    progress.job_done('p_rostest_t', 70.0, [present, os.path.join(folder, 'p', 'rosunit-t.xml')])
    progress.job_done('p_gtest_g', 3.0, [])
    stray = os.path.join(folder, 'p', 'stray.xml')
    with open(stray, 'w') as f:
        f.write('')
    progress.unclaimed([present, stray])
    assert out.getvalue().splitlines() == [
        '[ 1:15] ok   p/rostest-t.xml: 2 passed, 0 failed, 0 skipped (70 s)',
        '[ 1:15] FAIL p_rostest_t: no result file p/rosunit-t.xml',
        '[ 1:15] FAIL p/stray.xml: 0 passed, 1 failed, 0 skipped (0 s)']
    assert progress.slowest(2).splitlines() == ['slowest 2 test jobs (seconds each took):',
                                                '      70 s  p_rostest_t',
                                                '       3 s  p_gtest_g']


def test_a_stopped_run_ends_its_running_jobs_and_x_servers(tmp_path):
    folder = str(tmp_path)
    stopped = []

    class Display(FakeDisplay):
        def stop(self):
            stopped.append(True)

    runner = test_runner.Runner([], 1, folder, Progress(folder, io.StringIO()), '/dev/null',
                                display=Display)
    runner.displays.append(Display())
    job = subprocess.Popen(['/bin/sh', '-c', 'sleep 300 & wait'], start_new_session=True)
    runner.started['hangs'] = job
    with pytest.raises(SystemExit) as stop:
        runner.abort(15, None)
    assert stop.value.code == 128 + 15
    assert job.wait(timeout=10) != 0
    assert stopped == [True]
