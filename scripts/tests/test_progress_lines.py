"""The lines `make build` and `make test` print while they run (build_progress.py,
results_watch.py), fed with made-up output and result files and a hand-driven clock."""
import io
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import build_progress  # noqa: E402
import results_watch  # noqa: E402


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def test_a_line_when_a_package_starts_and_its_span_at_the_end():
    clock, out = Clock(), io.StringIO()
    progress = build_progress.Progress(out, clock)
    clock.now = 5
    progress.line('[  3%] Building CXX object src/sim_render/CMakeFiles/sim_render.dir/src/a.cpp.o\n')
    clock.now = 65
    progress.line('[ 40%] Building CXX object src/bullet_sim/CMakeFiles/core.dir/src/b.cpp.o\n')
    clock.now = 70
    progress.line('[ 41%] Linking CXX shared library /ws/devel/lib/libsim_render.so src/sim_render/x\n')
    progress.line('/ws/src/bullet_sim/src/b.cpp:3:1: warning: unused variable\n')
    clock.now = 80
    progress.line('[ 42%] Built target sim_render\n')  # the end of sim_render's span
    progress.line('[ 43%] Built target some_other_target\n')  # not one of ours: nothing
    clock.now = 200
    progress.line('[ 99%] Linking CXX executable /ws/devel/lib/bullet_sim/node src/bullet_sim/y\n')
    lines = out.getvalue().splitlines()
    assert lines == ['[ 0:05] building sim_render', '[ 1:05] building bullet_sim',
                     '/ws/src/bullet_sim/src/b.cpp:3:1: warning: unused variable']
    summary = progress.summary().splitlines()
    assert summary[0] == '[ 3:20] build done; compile and link time per package:'
    assert summary[1].split()[:3] == ['sim_render', '75.0', 's']
    assert summary[2].split()[:3] == ['bullet_sim', '135.0', 's']


def test_a_long_compile_is_reported_every_heartbeat():
    clock, out = Clock(), io.StringIO()
    progress = build_progress.Progress(out, clock)
    clock.now = 20
    progress.heartbeat()  # 20 s of cmake: not yet
    clock.now = 26
    progress.heartbeat()
    clock.now = 30
    progress.line('[ 10%] Building CXX object src/bullet_sim/CMakeFiles/core.dir/src/a.cpp.o\n')
    clock.now = 31
    progress.line('[ 11%] Building CXX object src/bullet_sim/CMakeFiles/core.dir/src/b.cpp.o\n')
    clock.now = 50
    progress.heartbeat()  # 20 s after the package's first line: quiet
    clock.now = 56
    progress.heartbeat()
    progress.heartbeat()  # just said: not again
    clock.now = 81
    progress.heartbeat()
    assert out.getvalue().splitlines() == [
        '[ 0:26] configuring', '[ 0:30] building bullet_sim',
        '[ 0:56] building bullet_sim: 2 files compiled so far',
        '[ 1:21] building bullet_sim: 2 files compiled so far']


def write_result(folder, name, passed, failed, mtime):
    cases = ''.join('<testcase classname="c" name="p%d"/>' % i for i in range(passed))
    cases += ''.join('<testcase classname="c" name="f%d"><failure message="no"/></testcase>' % i
                     for i in range(failed))
    path = os.path.join(folder, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w') as f:
        f.write('<testsuite>%s</testsuite>' % cases)
    os.utime(path, (mtime, mtime))
    return path


def test_a_line_per_finished_result_file_and_the_slowest_at_the_end():
    folder = tempfile.mkdtemp()
    clock, out = Clock(), io.StringIO()
    watcher = results_watch.Watcher(folder, out, clock, wall_clock=lambda: 2000.0)
    clock.now = 30
    write_result(folder, 'pkg_a/gtest-a.xml', 3, 0, 1000)
    watcher.poll()
    assert out.getvalue() == ''  # the newest file may still be rewritten
    clock.now = 130
    write_result(folder, 'pkg_b/rostest-b.xml', 1, 1, 1010)
    watcher.poll()
    watcher.poll()  # nothing new: nothing printed
    clock.now = 150
    watcher.poll(final=True)
    lines = out.getvalue().splitlines()
    assert lines == ['[ 2:10] ok   pkg_a/gtest-a.xml: 3 passed, 0 failed, 0 skipped (130 s)',
                     '[ 2:30] FAIL pkg_b/rostest-b.xml: 1 passed, 1 failed, 0 skipped (20 s)']
    assert watcher.slowest(1).splitlines() == ['slowest 1 result files (seconds since the one before):',
                                               '     130 s  pkg_a/gtest-a.xml']


def test_a_rostest_placeholder_is_not_reported_before_the_test_ends():
    # rostest writes a failing placeholder when its test starts and the real result at the
    # end: while it is the newest file it is not read.
    folder = tempfile.mkdtemp()
    out = io.StringIO()
    watcher = results_watch.Watcher(folder, out, Clock(), wall_clock=lambda: 2000.0)
    write_result(folder, 'pkg/gtest-a.xml', 2, 0, 1000)
    write_result(folder, 'pkg/rostest-b.xml', 0, 1, 1001)  # the placeholder
    watcher.poll()
    assert 'rostest-b' not in out.getvalue()
    write_result(folder, 'pkg/rostest-b.xml', 4, 0, 1050)  # the test's real result
    write_result(folder, 'pkg/gtest-c.xml', 1, 0, 1060)
    watcher.poll()
    assert 'pkg/rostest-b.xml: 4 passed, 0 failed' in out.getvalue()
    assert 'FAIL' not in out.getvalue()


def test_empty_result_files_of_a_running_rostest_wait_until_written():
    folder = tempfile.mkdtemp()
    out = io.StringIO()
    watcher = results_watch.Watcher(folder, out, Clock(), wall_clock=lambda: 2000.0)
    for name, mtime in (('pkg/rostest-t.xml', 1000), ('pkg/rosunit-t.xml', 1001)):
        path = os.path.join(folder, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        open(path, 'w').close()
        os.utime(path, (mtime, mtime))
    watcher.poll()
    assert out.getvalue() == ''
    write_result(folder, 'pkg/rostest-t.xml', 3, 0, 1100)
    write_result(folder, 'pkg/rosunit-t.xml', 3, 0, 1100)
    write_result(folder, 'pkg/next.xml', 1, 0, 1200)
    watcher.poll()
    assert 'pkg/rostest-t.xml: 3 passed, 0 failed' in out.getvalue()
    assert 'FAIL' not in out.getvalue()


def test_a_file_still_being_written_waits_for_the_next_poll():
    folder = tempfile.mkdtemp()
    out = io.StringIO()
    watcher = results_watch.Watcher(folder, out, Clock(), wall_clock=lambda: 1000.5)
    write_result(folder, 'pkg/gtest.xml', 1, 0, 1000)  # modified half a second ago
    write_result(folder, 'pkg/later.xml', 1, 0, 1000)
    watcher.poll()
    assert out.getvalue() == ''
    watcher.wall_clock = lambda: 1002.0
    watcher.poll()
    assert 'pkg/gtest.xml: 1 passed' in out.getvalue()
