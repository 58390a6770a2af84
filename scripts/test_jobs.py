#!/usr/bin/python3
"""The test jobs of a catkin build folder: one per ctest entry (a gtest binary, a pytest
file or a rostest launch file), with the result files it writes, its time limit, and the
group of jobs it must not run beside. The commands are catkin's own (`ctest
--show-only=json-v1` lists them: catkin's run_tests.py, which writes a failing result when
the test left none)."""
import json
import os
import shlex
import subprocess
import xml.etree.ElementTree as ET
from dataclasses import dataclass

# Jobs that must not run at the same time as another job of the same group:
# {job name: (group, why)}. Every other pair of jobs runs side by side: each rostest starts
# its own master on a free port, each worker has its own X server and ROS_HOME. None needs
# a group today: the RViz tests, the simulator's and the overlay builds all passed side by
# side on two and three workers.
GROUPS = {}

# Wall seconds a job may take when its own files name no limit (gtests, pytests).
DEFAULT_LIMIT_S = 900.0
# Added to the sum of a rostest's time-limits: master, launch and shutdown.
ROSTEST_MARGIN_S = 120.0
# Expected seconds of a job never measured, by kind, to start long ones first.
FIRST_GUESS_S = {'rostest': 60.0, 'pytests': 10.0, 'gtest': 5.0}


@dataclass
class Job:
    name: str
    package: str
    kind: str
    command: list
    cwd: str
    result_files: list  # the one catkin checks first, then those of a rostest's <test>s
    limit_s: float = DEFAULT_LIMIT_S
    group: str = None


class JobListError(RuntimeError):
    """The build folder's test list cannot be read."""


def ctest_entries(build_dir):
    """The `tests` of `ctest --show-only=json-v1` run in build_dir."""
    proc = subprocess.run(['ctest', '--show-only=json-v1'], cwd=build_dir,
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise JobListError(f'{build_dir}: ctest --show-only=json-v1 failed: {proc.stderr.strip()}')
    return json.loads(proc.stdout).get('tests', [])


def job_from_ctest(entry):
    """A Job from one ctest entry: `_ctest_<package>_<kind>_<name>` running catkin's
    run_tests.py <result file> --return-code <commands...>."""
    command = entry['command']
    try:
        result = command[command.index('--return-code') - 1]
    except ValueError:
        raise JobListError(f"ctest entry {entry['name']}: no '--return-code' in {command}")
    package = os.path.basename(os.path.dirname(result))
    prefix = '_ctest_' + package + '_'
    if not entry['name'].startswith(prefix):
        raise JobListError(f"ctest entry {entry['name']}: result file {result} is not in a "
                           f"folder named after its package")
    name = entry['name'][len('_ctest_'):]
    kind = entry['name'][len(prefix):].split('_', 1)[0]
    cwd = next((p['value'] for p in entry.get('properties', [])
                if p['name'] == 'WORKING_DIRECTORY'), None)
    job = Job(name=name, package=package, kind=kind, command=command, cwd=cwd,
              result_files=[result], group=GROUPS.get(name, (None,))[0])
    if kind == 'rostest':
        add_rostest_parts(job, command[-1])
    return job


def add_rostest_parts(job, rostest_command):
    """A rostest writes one more result file per <test> (rosunit-<test-name>.xml beside its
    own) and may take the sum of their time-limits (rostest's default: 60 s)."""
    launch_file = shlex.split(rostest_command)[-1]
    try:
        root = ET.parse(launch_file).getroot()
    except (ET.ParseError, OSError) as err:
        raise JobListError(f'{job.name}: cannot read its launch file {launch_file}: {err}')
    folder = os.path.dirname(job.result_files[0])
    limit = 0.0
    for test in root.iter('test'):
        name = test.get('test-name')
        job.result_files.append(os.path.join(folder, f'rosunit-{name}.xml'))
        limit += float(test.get('time-limit', '60'))
    job.limit_s = limit + ROSTEST_MARGIN_S


def expected_s(job, durations):
    return durations.get(job.name, FIRST_GUESS_S.get(job.kind, 10.0))


def longest_first(jobs, durations):
    """Jobs ordered by their duration in the last run (a first guess by kind for new ones),
    longest first: the two workers then end at about the same time."""
    return sorted(jobs, key=lambda job: (-expected_s(job, durations), job.name))


def load_durations(path):
    try:
        with open(path) as f:
            return {str(k): float(v) for k, v in json.load(f).items()}
    except (OSError, ValueError, AttributeError):
        return {}


def save_durations(path, durations):
    with open(path, 'w') as f:
        json.dump(durations, f, indent=1, sort_keys=True)


def pytest_job(repo, results_dir):
    """The benchmark scripts' own checks (rates, sanity of the peers, their output parsing)
    and those of these test scripts; no simulator is started."""
    result = os.path.join(results_dir, 'bench', 'pytest-bench.xml')
    command = ['/usr/bin/python3', '-m', 'pytest', '-q', '-p', 'no:cacheprovider',
               'bench/', 'scripts/tests/', '--junitxml=' + result]
    return Job(name='bench_pytest', package='bench', kind='pytest', command=command, cwd=repo,
               result_files=[result])
