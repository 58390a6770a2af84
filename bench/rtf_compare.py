#!/usr/bin/python3
"""Real-time factors of two builds measured in the same run, as fast as possible on the
round track: one Burger in `bullet_sim_node` with every topic subscribed (sim_rtf.sh), the
same Burger in the core alone (bullet_sim_bench), and 16 Burgers in one node
(multi_robot.py). Each measurement runs the `before` and `after` devel spaces in turn, the
order alternating from round to round. Prints the median (range) of each and after/before,
with the load average before and after: the machine is shared, so builds are compared
within one run, not across runs. MuJoCo and PyBullet are the same in both, so the ratio
of two builds' real-time factors is the ratio of their leads over them.

Usage: rtf_compare.py [--rounds N] [--sim-seconds S] [--multi-sim-seconds S]
                      BEFORE_DEVEL AFTER_DEVEL
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

import ros_bench
import scenario

HERE = os.path.dirname(os.path.abspath(__file__))
RTF = re.compile(r"real-time factor ([0-9.]+)\s*$", re.M)


def without_workspace(env):
    """`env` without a sourced workspace, so that each build's own setup is the only one
    (a library path left from another devel space would load that build's libraries)."""
    env = dict(env)
    for name in ("LD_LIBRARY_PATH", "ROS_PACKAGE_PATH", "CMAKE_PREFIX_PATH", "PYTHONPATH",
                 "PKG_CONFIG_PATH", "ROSLISP_PACKAGE_DIRECTORIES"):
        env.pop(name, None)
    return env


def measurements(urdf, poses, args):
    """(name, command of a devel space) for each figure."""
    return (
        ("1 Burger, node", lambda devel: [os.path.join(HERE, "sim_rtf.sh"),
                                          str(args.sim_seconds)]),
        ("1 Burger, core", lambda devel: [os.path.join(devel, "lib/bullet_sim/bullet_sim_bench"),
                                          urdf, ros_bench.WORLD, str(args.sim_seconds)]),
        ("16 Burgers, node", lambda devel: [
            sys.executable, os.path.join(HERE, "multi_robot.py"),
            os.path.join(devel, "lib/bullet_sim/bench_rate_listener"), "16",
            str(args.multi_sim_seconds)]),
        ("16 Burgers, core", lambda devel: [
            os.path.join(devel, "lib/bullet_sim/bullet_sim_bench"), urdf, ros_bench.WORLD,
            str(args.multi_sim_seconds), poses]),
    )


def run_once(command, devel):
    env = dict(without_workspace(os.environ), BENCH_DEVEL=devel)
    out = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, timeout=600).stdout
    found = RTF.findall(out)
    if not found:
        raise RuntimeError("%s with %s printed no real-time factor:\n%s"
                           % (" ".join(command), devel, out))
    return float(found[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--sim-seconds", type=float, default=60.0)
    parser.add_argument("--multi-sim-seconds", type=float, default=20.0)
    parser.add_argument("before")
    parser.add_argument("after")
    args = parser.parse_args()
    names = ("before", "after")
    devels = dict(zip(names, (os.path.abspath(args.before), os.path.abspath(args.after))))
    work = ros_bench.work_folder("bench_rtf_compare_")
    env = ros_bench.ros_env(int(os.environ.get("BENCH_ROS_PORT", "11463")), devels["after"])
    urdf = ros_bench.burger_urdf(env, os.path.join(work, "burger.urdf"))
    poses = os.path.join(work, "poses_16.txt")
    scenario.write_circle_starts(ros_bench.WORLD, 16, poses)
    figures = measurements(urdf, poses, args)
    results = {name: {build: [] for build in names} for name, _ in figures}
    print("load average before: %s" % ros_bench.load_average())
    for round_index in range(args.rounds):
        order = names if round_index % 2 == 0 else names[::-1]
        for name, command in figures:
            for build in order:
                results[name][build].append(run_once(command(devels[build]), devels[build]))
    print("load average after: %s" % ros_bench.load_average())
    print("\nreal-time factor, median (range) of %d rounds" % args.rounds)
    print("| figure | before | after | after / before |")
    print("|---|---|---|---|")
    for name, _ in figures:
        before, after = (results[name][build] for build in names)
        print("| %s | %s | %s | %.2f |" % (name, ros_bench.median_range(before, 1),
                                           ros_bench.median_range(after, 1),
                                           statistics.median(after) / statistics.median(before)))


if __name__ == "__main__":
    main()
