"""bullet_sim.batch on a two-node Ray cluster (loopback): 4 seeded episodes of a fixed action
sequence give the returns and final observations of the same episodes in-process, to the
bit, and ran on both nodes. Ray lives in build/learning_venv (`make learning`), never in the
system's Python: the check runs in a subprocess with that interpreter (or with this one
when it has Ray), under a time limit."""

import importlib.util
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
WORKSPACE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(HERE))))
CHECK = os.path.join(HERE, 'ray_cluster_check.py')
LEARNING_PYTHON = os.path.join(WORKSPACE, 'build', 'learning_venv', 'bin', 'python')
TIMEOUT = 180  # s: two `ray start`s, 2 actors, 8 short episodes on a loaded 2-core machine


def ray_python():
    if importlib.util.find_spec('ray') is not None:
        return sys.executable
    if os.access(LEARNING_PYTHON, os.X_OK):
        return LEARNING_PYTHON
    return None


def test_batch_on_two_ray_nodes_equals_in_process():
    python = ray_python()
    if python is None:
        pytest.skip('Ray is not installed: make learning')
    pytest.importorskip('gymnasium', reason='gymnasium is not installed (make setup)')
    try:
        out = subprocess.run([python, CHECK], capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired as e:
        pytest.fail(f'{CHECK} took over {TIMEOUT} s:\n{e.stdout}\n{e.stderr}')
    assert out.returncode == 0, f'{CHECK} failed:\n{out.stdout}\n{out.stderr[-5000:]}'
    assert out.stdout.strip().splitlines()[-1].startswith('ok: 4 episodes on 2 nodes')
