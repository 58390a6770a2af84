#!/usr/bin/python3
"""Launch to first /scan of two builds, measured in the same run: `first_scan.py` with
BENCH_DEVEL set to each devel space in turn, both modes (own-master, running-master),
alternating, N rounds. Prints, per mode, the median (range) of every stage of each build,
of the spans before and after the simulator's process started, and the ratios, with the
load average before and after (the machine is shared: compare builds within one run, not
across runs).

Usage: first_scan_compare.py [--rounds N] BEFORE_DEVEL AFTER_DEVEL
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

import ros_bench

HERE = os.path.dirname(os.path.abspath(__file__))
MODES = ("running-master", "own-master")
PROCESS = "simulator process started (gzserver, then bullet_sim_node)"
LAUNCH = "launch to first /scan"
# Spans of one run, each from the stage before "->" to the one after it: what roslaunch
# and xacro take before the simulator starts, and what the simulator's side takes from
# then on (its medians are steadier than the launch's on a shared machine).
SPANS = (("roslaunch start -> simulator process started", None, PROCESS),
         ("simulator process started -> spawn service up", PROCESS,
          "/gazebo/spawn_urdf_model up (node started, world loaded)"),
         ("simulator process started -> first /scan", PROCESS, LAUNCH))
STAGE_LINE = re.compile(r"^\s+([0-9.]+|-)\s+s\s+(.*)$")
LAUNCH_LINE = re.compile(r"^launch to first /scan \((.*)\) ([0-9.]+) s$")


def run_once(devel, mode):
    """{stage: seconds} of one first_scan.py run of `devel` in `mode`."""
    env = dict(os.environ, BENCH_DEVEL=devel)
    out = subprocess.run([sys.executable, os.path.join(HERE, "first_scan.py"), mode], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, timeout=180).stdout
    stages = {}
    for line in out.splitlines():
        stage = STAGE_LINE.match(line)
        if stage and stage.group(1) != "-":
            stages[stage.group(2)] = float(stage.group(1))
        if LAUNCH_LINE.match(line):
            stages["launch to first /scan"] = float(LAUNCH_LINE.match(line).group(2))
    if LAUNCH not in stages:
        raise RuntimeError("first_scan.py %s with %s failed:\n%s" % (mode, devel, out))
    for name, begin, end in SPANS:
        stages[name] = stages[end] - (stages[begin] if begin else 0.0)
    return stages


def report(mode, names, results):
    print("\n%s, median (range) in s of %d rounds" % (mode, len(results[names[0]])))
    spans = [span[0] for span in SPANS]
    stages = [s for s in results[names[0]][0] if s != LAUNCH and s not in spans]
    stages += [LAUNCH] + spans
    print("| stage | %s | %s |" % names)
    print("|---|---|---|")
    for stage in stages:
        cells = []
        for name in names:
            values = [r[stage] for r in results[name] if stage in r]
            cells.append(ros_bench.median_range(values) if values else "-")
        print("| %s | %s | %s |" % (stage, cells[0], cells[1]))
    for row in (LAUNCH, SPANS[2][0]):
        before, after = (statistics.median(r[row] for r in results[n]) for n in names)
        print("%s (%s): %.3f s -> %.3f s, %.2fx" % (row, mode, before, after, before / after))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("before")
    parser.add_argument("after")
    args = parser.parse_args()
    names = ("before", "after")
    devels = dict(zip(names, (args.before, args.after)))
    results = {mode: {name: [] for name in names} for mode in MODES}
    print("load average before: %s" % ros_bench.load_average())
    for round_index in range(args.rounds):
        order = names if round_index % 2 == 0 else names[::-1]
        for mode in MODES:
            for name in order:
                results[mode][name].append(run_once(devels[name], mode))
    print("load average after: %s" % ros_bench.load_average())
    for mode in MODES:
        report(mode, names, results[mode])


if __name__ == "__main__":
    main()
