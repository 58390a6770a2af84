"""Tests of the benchmark's scenario and sanity checks (no simulator needed):
/usr/bin/python3 -m pytest bench/"""
import math
import os
import sys
import xml.etree.ElementTree as ET

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenario  # noqa: E402

WORLD = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                     "src/turtlebot3_gazebo/worlds/roundTrack.world")


def ray_range(origin, angle, segments):
    """First wall face along a ray, by intersecting it with each wall's two long faces."""
    dx, dy = math.cos(angle), math.sin(angle)
    best = math.inf
    for (x0, y0), (x1, y1), half in segments:
        ux, uy = x1 - x0, y1 - y0
        length = math.hypot(ux, uy)
        nx, ny = -uy / length, ux / length
        for side in (-half, half):
            px, py = x0 + side * nx, y0 + side * ny
            denom = dx * uy - dy * ux
            if abs(denom) < 1e-12:
                continue
            t = ((px - origin[0]) * uy - (py - origin[1]) * ux) / denom
            s = ((px - origin[0]) * dy - (py - origin[1]) * dx) / denom
            if t > 0 and 0 <= s <= 1:
                best = min(best, t)
    return best


def test_hand_computed_spawn_ranges_match_the_world_file():
    yaw = scenario.SPAWN_YAW_RAD
    lidar = (-0.032 * math.cos(yaw), -0.032 * math.sin(yaw))
    segments = scenario.wall_segments(WORLD)
    assert ray_range(lidar, yaw + math.pi / 2, segments) == pytest.approx(
        scenario.SPAWN_LEFT_RANGE_M, abs=1e-4)
    assert ray_range(lidar, yaw - math.pi / 2, segments) == pytest.approx(
        scenario.SPAWN_RIGHT_RANGE_M, abs=1e-4)


def test_spawn_scan_check_rejects_a_misplaced_wall():
    ranges = [math.inf] * scenario.RAY_COUNT
    ranges[90], ranges[270] = 0.802, 0.535
    scenario.check_spawn_scan(ranges, "peer")
    ranges[270] = 0.535 + 0.05
    with pytest.raises(scenario.SanityError,
                       match="ray 270 at the spawn pose reads 0.5850 m, the wall table gives"):
        scenario.check_spawn_scan(ranges, "peer")


def test_a_world_without_one_wall_is_refused(tmp_path):
    tree = ET.parse(WORLD)
    world = tree.getroot().find("world")
    world.remove(world.find("model[@name='wall_07']"))
    broken = tmp_path / "broken.world"
    tree.write(broken)
    with pytest.raises(scenario.SanityError, match="20 walls, the round track has 21"):
        scenario.read_world(str(broken))


def test_wheel_speeds_of_the_command():
    # (0.1 -+ 0.3 * 0.08) / 0.033
    left, right = scenario.wheel_speeds_radps(0.1, 0.3)
    assert left == pytest.approx(0.076 / 0.033)
    assert right == pytest.approx(0.124 / 0.033)


def test_track_accepts_the_commanded_arc_and_refuses_a_robot_at_rest():
    radius, sim_s = scenario.CIRCLE_RADIUS_M, 30.0
    track, still = scenario.Track(), scenario.Track()
    for k in range(int(sim_s * 30) + 1):
        heading = scenario.CMD_ANGULAR_RADPS * k / 30.0
        track.add(radius * math.sin(heading), radius * (1 - math.cos(heading)), heading)
        still.add(0.0, 0.0, 0.0)
    track.check(sim_s, "peer")
    with pytest.raises(scenario.SanityError, match="drove 0.00 m and turned 0.00 rad"):
        still.check(sim_s, "peer")


def test_sixteen_circles_clear_of_walls_and_of_each_other():
    poses = scenario.circle_starts(WORLD, 16)
    assert poses[0] == (0.0, 0.0, scenario.SPAWN_YAW_RAD)
    segments = scenario.wall_segments(WORLD)
    radius = scenario.CIRCLE_RADIUS_M
    centres = [(x - radius * math.sin(yaw), y + radius * math.cos(yaw)) for x, y, yaw in poses]
    for cx, cy in centres:
        for k in range(72):  # every robot position on the circle keeps its reach from walls
            a = 2 * math.pi * k / 72
            point = (cx + radius * math.cos(a), cy + radius * math.sin(a))
            assert min(scenario.distance_to_segment(point, s) for s in segments) > 0.12
    for i, a in enumerate(centres):
        for b in centres[i + 1:]:
            assert math.hypot(a[0] - b[0], a[1] - b[1]) >= 2 * (radius + scenario.ROBOT_REACH_M)


def test_the_poses_file_reads_back_as_the_poses(tmp_path):
    poses = scenario.circle_starts(WORLD, 4)
    path = scenario.write_circle_starts(WORLD, 4, str(tmp_path / "starts.txt"))
    with open(path) as f:
        read = [tuple(float(v) for v in line.split()) for line in f]
    assert read == poses
