#!/usr/bin/python3
"""Runs lane_following.py against ROBOTIS's turtlebot3_autorace_2020.launch on a master of
its own, as the user's overlay has it built (src/turtlebot3_gazebo/README.md, Autonomous
driving). Its Gazebo window (gzclient) is started without a display: it exits, the rest
runs. The overlay is the one MOBILITY_AUTORACE_WS names (its devel/setup.bash is sourced for
every command: `make`'s test targets set up this workspace's environment alone), else the
environment's own.

    run_autorace.py [--mode lane|control] [--runs N] [--figures-dir DIR]

prints each run's figures (JSON) and exits non-zero if a run failed.
"""
import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', 'mobility_testing', 'src'))
from mobility_testing.ports import free_port  # noqa: E402

# The packages of the three clones (and of image_transport_plugins on Debian 12) that the
# chapter needs, with the launch file that tells ROBOTIS's turtlebot3_gazebo from ours.
NEEDED = ['turtlebot3_autorace_camera', 'turtlebot3_autorace_detect',
          'turtlebot3_autorace_driving', 'compressed_image_transport']
LAUNCH_TIMEOUT_S = 1500


def environment():
    return dict(os.environ, PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''),
                TURTLEBOT3_MODEL='burger', DISPLAY='')


def in_overlay(words):
    """A command run with MOBILITY_AUTORACE_WS's setup sourced first, when it is set."""
    overlay = os.environ.get('MOBILITY_AUTORACE_WS', '')
    if not overlay:
        return words
    setup = os.path.join(overlay, 'devel', 'setup.bash')
    return ['bash', '-c', 'source "$0" && exec "$@"', setup] + words


def missing():
    """What of the overlay is not built, as a sentence; '' when all is there."""
    env = environment()
    overlay = os.environ.get('MOBILITY_AUTORACE_WS', '')
    if overlay and not os.path.exists(os.path.join(overlay, 'devel', 'setup.bash')):
        return 'MOBILITY_AUTORACE_WS=%s has no devel/setup.bash (not built)' % overlay
    absent = [p for p in NEEDED if subprocess.run(
        in_overlay(['rospack', 'find', p]), stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL, env=env).returncode != 0]
    gazebo = subprocess.run(in_overlay(['rospack', 'find', 'turtlebot3_gazebo']),
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            universal_newlines=True, env=env)
    if not os.path.exists(os.path.join(gazebo.stdout.strip(), 'launch',
                                       'turtlebot3_autorace_2020.launch')):
        absent.append("ROBOTIS's turtlebot3_gazebo (turtlebot3_simulations, noetic)")
    if not absent:
        return ''
    return ('not built: %s (build the AutoRace overlay and set MOBILITY_AUTORACE_WS to it, '
            'or source it: src/turtlebot3_gazebo/README.md, Autonomous driving)'
            % ', '.join(absent))


def run_once(mode, figures_file, log_dir):
    """One run: the simulation launch, then lane_following.py; returns (exit code, output)."""
    port = free_port()
    env = dict(environment(), ROS_MASTER_URI='http://localhost:%d' % port)
    sim_log = open(os.path.join(log_dir, 'turtlebot3_autorace_2020.log'), 'w')
    sim = subprocess.Popen(in_overlay(['roslaunch', '-p', str(port), 'turtlebot3_gazebo',
                                       'turtlebot3_autorace_2020.launch']),
                           env=env, stdout=sim_log, stderr=subprocess.STDOUT,
                           start_new_session=True)
    try:
        test = subprocess.run(in_overlay(['/usr/bin/python3',
                                          os.path.join(HERE, 'lane_following.py'),
                                          '--mode', mode, '--figures', figures_file,
                                          '--logs', log_dir]),
                              env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, timeout=LAUNCH_TIMEOUT_S)
        return test.returncode, test.stdout
    finally:
        os.killpg(sim.pid, signal.SIGINT)
        try:
            sim.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(sim.pid, signal.SIGKILL)
            sim.wait()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--mode', choices=('lane', 'control'), default='lane')
    parser.add_argument('--runs', type=int, default=1)
    parser.add_argument('--figures-dir', default='')
    args = parser.parse_args()
    reason = missing()
    if reason:
        print(reason)
        return 2
    folder = args.figures_dir or tempfile.mkdtemp(prefix='autorace_')
    os.makedirs(folder, exist_ok=True)
    failed = 0
    for run in range(1, args.runs + 1):
        figures = os.path.join(folder, '%s_%d.json' % (args.mode, run))
        code, output = run_once(args.mode, figures, folder)
        print(output[-3000:] if code else '')
        shown = json.load(open(figures)) if os.path.exists(figures) else None
        if shown:
            shown.pop('trace', None)
        print('run %d (%s): exit %d, figures %s' % (run, args.mode, code, json.dumps(shown)))
        failed += code != 0
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
