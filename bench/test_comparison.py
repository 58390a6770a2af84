"""Tests of bench/compare's parsing, alternation and table: /usr/bin/python3 -m pytest bench/"""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from comparison import RTF, Measurement, alternated, last_line, table  # noqa: E402


def test_parse_takes_the_last_figure_of_each_pattern():
    m = Measurement(["x"], [("core", "core", RTF, "x"), ("mem", "memory", r"([0-9.]+) MB", "MB")])
    output = ("process CPU time 0.2 s: real-time factor per CPU second 145.8\n"
              "sim 30.0 s in 0.311 s wall: real-time factor 96.4\n12.5 MB\n")
    assert m.parse(output) == {"core": 96.4, "mem": 12.5}
    with pytest.raises(ValueError, match="memory: no figure"):
        m.parse("real-time factor 3\n")


def test_rtf_pattern_reads_the_peers_lines():
    m = Measurement(["x"], [("mujoco", "mujoco", RTF, "x")])
    assert m.parse("mujoco real-time factor 104.8 (30.0 s sim in 0.29 s wall)\n") == {
        "mujoco": 104.8}


def test_rounds_rotate_each_group():
    a, b, c = (Measurement([n], [(n, n, RTF, "x")]) for n in "abc")
    d, e = (Measurement([n], [(n, n, RTF, "x")], group=1) for n in "de")
    keys = [[m.key for m in alternated([a, b, c, d, e], r)] for r in range(3)]
    assert keys == [list("abcde"), list("bcaed"), list("cabde")]


def test_table_and_last_line_give_ratios_to_the_peers():
    results = {"node": [100, 90, 110], "core": [160], "mujoco": [120, 118, 124],
               "pybullet": [20], "camera_ours": [0.5], "camera_mujoco": [5.0]}
    ms = [Measurement([k], [(k, k, RTF, "ms" if "camera" in k else "x")]) for k in results]
    text = table(ms, results)
    assert "| node | 100x (90-110) | 0.83x MuJoCo, 5.00x PyBullet |" in text
    assert "| pybullet | 20.0x (20.0-20.0) |" in text
    assert "| camera_ours | 0.50 ms (0.50-0.50) | 10.00x MuJoCo |" in text
    assert last_line(results, (1.5, 2.25, 3.0)) == (
        "vs_mujoco_node=0.83 vs_mujoco_core=1.33 vs_mujoco_camera=10.00 vs_pybullet_node=5.00 "
        "loadavg=1.50/2.25/3.00")


def test_last_line_adds_depth_and_the_robot_figures():
    results = {"node": [100], "core": [160], "mujoco": [120], "pybullet": [20],
               "camera_ours": [0.5], "camera_mujoco": [5.0], "depth_ours": [0.6],
               "depth_mujoco": [6.0], "textured_ours": [2.0, 2.5], "textured_mujoco": [10.0],
               "robots_1": [70, 74, 80], "robots_16": [5.2, 5.3, 6.1],
               "robots_core_16": [9.0], "robots_core_16_1thread": [6.3],
               "launch_own": [1.31, 1.194, 1.25], "launch_running": [0.987],
               "launch_sim_own": [0.52, 0.498], "launch_sim_running": [0.471],
               "memory": [26.84, 26.9, 27.0]}
    assert last_line(results, (1.0, 1.0, 1.0)) == (
        "vs_mujoco_node=0.83 vs_mujoco_core=1.33 vs_mujoco_camera=10.00 vs_mujoco_depth=10.00 "
        "vs_mujoco_camera_textured=4.44 vs_pybullet_node=5.00 robots_1=74.0 robots_16=5.3 "
        "robots_core_16=9.0 robots_core_16_1thread=6.3 launch_own=1.25 launch_running=0.99 launch_sim_own=0.51 "
        "launch_sim_running=0.47 memory=26.9 loadavg=1.00/1.00/1.00")
