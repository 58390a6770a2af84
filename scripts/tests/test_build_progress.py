"""The lines `make build` and the test programs' build print while they run
(build_progress.py, test_build.py), fed with made-up output and a hand-driven clock."""
import io
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import build_progress  # noqa: E402
from hand_clock import Clock  # noqa: E402


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


def test_a_long_compile_is_reported_after_25_quiet_seconds():
    clock, out = Clock(), io.StringIO()
    progress = build_progress.Progress(out, clock)
    clock.now = 20
    progress.heartbeat()  # 20 s of cmake: not yet
    clock.now = 26
    progress.heartbeat()
    clock.now = 30
    progress.line('[ 10%] Building CXX object src/bullet_sim/CMakeFiles/core.dir/src/a.cpp.o\n')
    clock.now = 31
    progress.line('[ 12%] Building CXX object src/bullet_sim/CMakeFiles/core.dir/src/b.cpp.o\n')
    clock.now = 50
    progress.heartbeat()  # 20 s after the package's first line: quiet
    clock.now = 56
    progress.heartbeat()
    progress.heartbeat()  # just said: not again
    progress.line('[ 55%] Linking CXX executable /ws/devel/lib/bullet_sim/test_x src/bullet_sim/t\n')
    clock.now = 81
    progress.heartbeat()
    assert out.getvalue().splitlines() == [
        '[ 0:26] configuring', '[ 0:30] building bullet_sim',
        '[ 0:56] building bullet_sim: 2 files compiled so far, make at 12%',
        '[ 1:21] building bullet_sim: 2 files compiled so far, make at 55%']


def test_the_test_build_keeps_the_whole_output_and_its_status(tmp_path):
    folder = str(tmp_path)
    log = os.path.join(folder, 'build.log')
    script = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                          'test_build.py')
    proc = subprocess.run([sys.executable, script, '--log', log, '--', '/bin/sh', '-c',
                           'echo "a.cpp:1:1: error: boom"; echo quiet line; exit 2'],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert proc.stdout == 'a.cpp:1:1: error: boom\n'
    with open(log) as f:
        assert f.read() == 'a.cpp:1:1: error: boom\nquiet line\n'
