"""rtf_compare.py's pieces that do not need two builds: each build runs with its own
environment only, and the real-time factor is read from a run's last figure line."""
import pytest

import ros_bench
import rtf_compare


def test_a_sourced_workspace_is_left_out_of_the_environment():
    env = {"PATH": "/usr/bin", "HOME": "/root", "LD_LIBRARY_PATH": "/ws/devel/lib",
           "ROS_PACKAGE_PATH": "/ws/src", "CMAKE_PREFIX_PATH": "/ws/devel",
           "PYTHONPATH": "/ws/devel/lib/python3/dist-packages"}
    assert rtf_compare.without_workspace(env) == {"PATH": "/usr/bin", "HOME": "/root"}


def test_the_last_real_time_factor_line_is_the_figure():
    out = ("bullet_sim, round track:\nodom 30.0 Hz\nreal-time factor per CPU second 125.0\n"
           "sim 60.0 s in 0.48 s wall: real-time factor 124.9\n")
    assert rtf_compare.RTF.findall(out)[-1] == "124.9"


def test_a_run_without_a_figure_names_the_command_and_build():
    with pytest.raises(RuntimeError, match="/bin/echo no figure with /some/devel"):
        rtf_compare.run_once(["/bin/echo", "no", "figure"], "/some/devel")


def test_median_and_range():
    assert ros_bench.median_range([3.0, 1.0, 2.5], 1) == "2.5 (1.0-3.0)"
