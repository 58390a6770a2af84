"""bullet_sim's Python module against hand-derived geometry and kinematics."""
import gc
import math
import os
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import bullet_sim
from conftest import FIXTURES, PACKAGE, SPAWN_YAW, WORKSPACE


def forward_limit_mps2():
    """How hard the Burger can speed up before its tyres slip (mu 0.1 on every contact):
    a = mu g (L - 2 d) / (L + 2 mu h), L the caster's ground contact behind the axle, d and h
    the centre of mass behind the axle and above the ground, with the robot resting pitched
    back about the axle until the caster's edge touches (test/core/burger_drive_model.h works
    the same figures out from the URDF: 0.825 m/s^2)."""
    mu, g, axle_z = 0.1, 9.8, 0.033
    edge_x, edge_z = -0.096, 0.0015 - axle_z   # caster edge, from the axle
    com_x, com_z = -0.00411, 0.0395 - axle_z   # centre of mass, from the axle
    r = math.hypot(edge_x, edge_z)
    p = math.asin(axle_z / r) - math.atan2(-edge_z, -edge_x)
    c, s = math.cos(p), math.sin(p)
    caster_behind = -(edge_x * c - edge_z * s)
    com_behind = -(com_x * c - com_z * s)
    com_height = axle_z + com_x * s + com_z * c
    return mu * g * (caster_behind - 2 * com_behind) / (caster_behind + 2 * mu * com_height)


def test_drive_straight_goes_v_t_less_the_slip_of_getting_going(make_sim):
    sim = make_sim()
    sim.step(1000)  # settle on the ground; 1 s is a whole number of drive periods (1/30 s)
    start = sim.model_pose('burger')
    sim.set_cmd_vel('burger', 0.1, 0.0)
    sim.step(2000)
    end = sim.model_pose('burger')
    assert sim.time == pytest.approx(3.0, abs=1e-9)
    v, t = 0.1, 2.0
    # The rims ramp at 1 m/s^2, faster than the tyres grip: the body reaches v at the tyres'
    # limit a and then runs at v, v t - v^2 / (2 a) = 0.1939 m (0.2 m were it to start at v).
    expected = v * t - v * v / (2 * forward_limit_mps2())
    heading = np.array([math.cos(start.yaw), math.sin(start.yaw)])
    advanced = float(np.dot(end.position[:2] - start.position[:2], heading))
    assert advanced == pytest.approx(expected, abs=0.001)
    assert abs(end.yaw - start.yaw) < 0.01
    # Odometry (world source in the Burger's plugin) says the same.
    odom = sim.read_odometry('burger')
    assert odom.twist.linear[0] == pytest.approx(v, abs=0.005)
    assert odom.time == pytest.approx(3.0, abs=1e-9)


def wall_range(scanner_xy, heading, face_x):
    """Range along a horizontal ray from `scanner_xy` at world `heading` to the plane x =
    face_x (a wall of yaw 0 of DESIGN.md's table, long enough to be hit)."""
    return (face_x - scanner_xy[0]) / math.cos(heading)


def test_scan_ranges_to_the_lane_walls_match_the_wall_table(make_sim):
    sim = make_sim()
    sim.step(200)
    scan = sim.read_scan('burger')
    assert scan.ranges.dtype == np.float32 and scan.ranges.shape == (360,)
    assert scan.frame_id == 'base_scan'
    assert scan.angle_increment == pytest.approx(6.28319 / 359, abs=1e-12)
    assert (scan.range_min, scan.range_max) == pytest.approx((0.12, 3.5))
    # base_scan is 0.032 m behind base_footprint (scan_joint); walls are 0.015 m thick.
    scanner = (-0.032 * math.cos(SPAWN_YAW), -0.032 * math.sin(SPAWN_YAW))
    west_face = -0.80941 + 0.0075   # wall (-0.80941, 0.25461, yaw 0, 6.0)
    inner_face = 0.54193 - 0.0075   # wall (0.54193, 0.34703, yaw 0, 3.8)
    for i, face in ((90, west_face), (270, inner_face)):
        heading = SPAWN_YAW + scan.angle_min + i * scan.angle_increment
        # the LDS's noise has stddev 0.01 m: 4 sigma
        assert scan.ranges[i] == pytest.approx(wall_range(scanner, heading, face), abs=0.04), i


def test_same_seed_gives_bit_identical_runs_and_another_seed_other_noise(make_sim):
    def run(seed):
        sim = make_sim(seed=seed)
        sim.set_cmd_vel('burger', 0.15, 0.4)
        scans, poses = [], []
        for _ in range(5):
            sim.step(200)
            scans.append(sim.read_scan('burger').ranges)
            poses.append(sim.model_pose('burger').to_tuple())
        return np.stack(scans), poses
    scans1, poses1 = run(7)
    scans2, poses2 = run(7)
    assert scans1.tobytes() == scans2.tobytes()
    assert poses1 == poses2
    scans3, poses3 = run(8)
    finite = np.isfinite(scans1) & np.isfinite(scans3)
    assert finite.sum() > 100
    # The LDS has gaussian noise (stddev 0.01 m): another seed, other ranges, nearly all
    # of them (the ranges are rounded to the lidar's 0.015 m, so some agree by chance).
    assert (scans1[finite] != scans3[finite]).mean() > 0.3
    assert poses3 == pytest.approx(poses1, abs=1e-9)  # the physics draws no noise


def test_reset_returns_to_the_spawn_pose_and_time_zero(make_sim):
    sim = make_sim()
    spawn = sim.model_pose('burger')
    assert spawn.position == pytest.approx([0, 0, 0], abs=1e-9)
    assert spawn.yaw == pytest.approx(SPAWN_YAW, abs=1e-12)
    sim.set_cmd_vel('burger', 0.2, 0.5)
    sim.step(1500)
    assert np.linalg.norm(sim.model_pose('burger').position[:2]) > 0.1
    sim.reset()
    assert sim.time == 0.0
    back = sim.model_pose('burger')
    assert back.to_tuple() == pytest.approx(spawn.to_tuple(), abs=1e-9)
    assert np.abs(sim.model_twist('burger').linear).max() == pytest.approx(0, abs=1e-9)
    sim.step(500)  # the command was zeroed: it stays where it is
    assert np.linalg.norm(sim.model_pose('burger').position[:2]) < 0.002


def test_step_to_next_reading_stops_at_the_due_sensor(make_sim):
    sim = make_sim()
    # The IMU (200 Hz in turtlebot3_burger.gazebo.xacro) is due every 5 steps.
    due = sim.step_to_next_reading(1000)
    assert sim.time == pytest.approx(0.005, abs=1e-9)
    assert [(d.robot, d.kind, d.index) for d in due] == [('burger', bullet_sim.SensorKind.IMU, 0)]
    assert len({due[0], sim.step_to_next_reading(1000)[0]}) == 1  # equal and hashable
    # The lidar (5 Hz) at 0.2 s, among the IMU's readings.
    for _ in range(100):
        due = sim.step_to_next_reading(1000)
        if any(d.kind == bullet_sim.SensorKind.RAY for d in due):
            break
    assert sim.time == pytest.approx(0.2, abs=1e-9)
    assert sim.read_scan('burger').time == pytest.approx(0.2, abs=1e-9)


def test_broken_urdf_raises_load_error_naming_file_and_element():
    path = os.path.join(FIXTURES, 'urdf_negative_mass.urdf')
    with pytest.raises(bullet_sim.LoadError) as err:
        bullet_sim.Robot.from_urdf(path)
    assert path in str(err.value)
    assert 'base_link' in str(err.value) and 'mass' in str(err.value)
    with pytest.raises(bullet_sim.LoadError) as err:
        bullet_sim.Robot.from_urdf('/nonexistent/robot.urdf')
    assert '/nonexistent/robot.urdf' in str(err.value)
    with open(path) as f:
        text = f.read()
    with pytest.raises(bullet_sim.LoadError) as err:
        bullet_sim.Robot.from_urdf(text, 'my_robot')
    assert 'my_robot' in str(err.value)
    with pytest.raises(bullet_sim.LoadError) as err:
        bullet_sim.World.from_file('/nonexistent/x.world')
    assert '/nonexistent/x.world' in str(err.value)


def test_unknown_names_and_bad_arguments(make_sim, burger):
    sim = make_sim()
    with pytest.raises(KeyError) as err:
        sim.model_pose('nope')
    assert "'nope'" in str(err.value)
    for call in (lambda: sim.set_cmd_vel('nope', 0.1, 0), lambda: sim.read_scan('nope'),
                 lambda: sim.read_odometry('nope'), lambda: sim.step_to_next_reading(0) or
                 sim.condition('nope')):
        with pytest.raises((KeyError, ValueError)):
            call()
    with pytest.raises(IndexError) as err:
        sim.read_scan('burger', 1)
    assert str(err.value) == "robot 'burger' has 1 ray sensor(s): no index 1"
    with pytest.raises(bullet_sim.LoadError):
        sim.spawn('burger', burger)  # a name clash
    with pytest.raises(ValueError):
        sim.set_cmd_vel('burger', float('nan'), 0)
    with pytest.raises(ValueError):
        sim.spawn('b2', burger, (0, 0, 0))
    with pytest.raises(ValueError):
        sim.step(0)
    with pytest.raises(ValueError):
        bullet_sim.Simulation(sim.world, physics_step=0)
    assert sim.delete('nope') is False


def test_spawn_delete_and_model_state(make_sim, burger):
    sim = make_sim()
    sim.spawn('b2', burger, (1.5, 0.3, 0.0, 0.0, 0.0, 0.0, 1.0))
    assert sim.robot_names() == ['burger', 'b2']
    sim.set_model_state('b2', (2.0, -0.5, 0.0, math.pi / 2))
    pose = sim.model_pose('b2')
    assert (pose.x, pose.y, pose.yaw) == pytest.approx((2.0, -0.5, math.pi / 2), abs=1e-9)
    # The base's collision box (0.140 long, centre 0.032 behind base_footprint) has its front
    # 0.038 m ahead of base_footprint; put 0.03 m into the inner wall's face (x 0.53443):
    sim.set_model_state('b2', (0.54193 - 0.0075 - 0.038 + 0.03, 1.0, 0.0, 0.0))
    sim.step()  # contacts are found in a step
    condition = sim.condition('b2')
    assert condition.in_wall and not condition.tipped_over
    assert condition.wall_penetration == pytest.approx(0.03, abs=0.002)
    assert not sim.condition('burger').in_wall
    assert sim.delete('b2') is True
    assert sim.robot_names() == ['burger']


def test_arrays_own_their_memory(make_sim):
    sim = make_sim()
    sim.step(200)
    scan = sim.read_scan('burger')
    joints = sim.read_joint_states('burger')
    image = sim.read_camera('burger')
    ranges = scan.ranges
    before = ranges.copy()
    assert ranges.flags.writeable and ranges.base is not None  # its vector, freed with it
    assert joints.positions.dtype == np.float64 and joints.positions.shape == (len(joints.names),)
    assert image.dtype == np.uint8 and image.shape == (480, 640, 3)
    imu = sim.read_imu('burger')
    for vector in (imu.angular_velocity, imu.linear_acceleration):
        assert vector.dtype == np.float64 and vector.shape == (3,)
    assert imu.orientation.shape == (4,)
    assert imu.linear_acceleration[2] == pytest.approx(9.8, abs=0.1)  # at rest: +g up
    odom = sim.read_odometry('burger')
    assert odom.pose_covariance.shape == (6, 6) and odom.twist_covariance.shape == (6, 6)
    image_before = image.copy()
    del sim, scan
    gc.collect()
    # Other allocations that would reuse freed memory:
    junk = [np.ones(360, np.float32) * 99 for _ in range(100)]
    assert np.array_equal(ranges, before, equal_nan=True)
    assert np.array_equal(image, image_before)
    ranges[0] = 1.0  # writable without touching anything else
    del junk


def test_camera_sees_the_brown_walls(make_sim):
    sim = make_sim()
    image = sim.read_camera('burger')
    # The camera looks along the lane (+y); the walls' diffuse colour is 0.57 0.417 0.25:
    # red above green above blue, wherever a wall is seen; the grey ground has r = g = b.
    mean = image.reshape(-1, 3).astype(float).mean(axis=0)
    assert mean[0] > mean[1] > mean[2]
    with pytest.raises(IndexError):
        sim.read_camera('burger', 1)


def test_two_threads_step_two_simulations_as_sequentially(make_sim):
    def run(sim, out):
        sim.set_cmd_vel('burger', 0.2, -0.3)
        for _ in range(5):
            sim.step(400)
            out.append((sim.model_pose('burger').to_tuple(), sim.read_scan('burger').ranges))
    sequential = []
    for seed in (3, 4):
        out = []
        run(make_sim(seed=seed), out)
        sequential.append(out)
    parallel = [[], []]
    sims = [make_sim(seed=3), make_sim(seed=4)]
    threads = [threading.Thread(target=run, args=(sims[i], parallel[i])) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for seq, par in zip(sequential, parallel):
        assert len(seq) == len(par) == 5
        for (pose_s, ranges_s), (pose_p, ranges_p) in zip(seq, par):
            assert pose_s == pose_p
            assert ranges_s.tobytes() == ranges_p.tobytes()


def test_import_needs_only_the_devel_setup_and_no_ros():
    """`import bullet_sim` in a fresh shell that only sourced devel/setup.bash, no master
    (ROS_MASTER_URI pointing nowhere), and no ROS library loaded by the module; the import
    itself loads nothing compiled (clients of bullet_sim.srv import the same package)."""
    setup = os.path.join(WORKSPACE, 'devel', 'setup.bash')
    script = ('import sys, bullet_sim\n'
              'assert "bullet_sim._core" not in sys.modules  # loaded on first use\n'
              'world = bullet_sim.World.from_string("<sdf version=\'1.6\'><world name=\'w\'>'
              '</world></sdf>")\n'
              'sim = bullet_sim.Simulation(world)\n'
              'sim.step(10)\n'
              'print(round(sim.time, 6))\n'
              'print(sorted(m for m in sys.modules if m.split(".")[0] in '
              '("rospy", "roslib", "rosgraph", "genpy")))\n'
              'print(open("/proc/self/maps").read())\n')
    env = {'PATH': '/usr/bin:/bin', 'HOME': os.environ.get('HOME', '/tmp'),
           'ROS_MASTER_URI': 'http://127.0.0.1:1'}
    out = subprocess.run(['/bin/bash', '-c', 'source "$0" && exec /usr/bin/python3 -c "$1"',
                          setup, script], env=env, capture_output=True, text=True, timeout=60,
                         cwd='/')
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[0] == '0.01'
    assert lines[1] == '[]'
    maps = '\n'.join(lines[2:])
    assert '_core.' in maps
    assert 'libroscpp' not in maps and 'librosconsole' not in maps


def test_stepping_releases_the_gil(make_sim):
    """While one thread is inside a long step(), the main thread keeps running Python: the
    longest pause between its loop's turns stays well below the call's length (a call that
    held the GIL would stop it for all of the call)."""
    sim = make_sim(threads=1)
    call = []

    def step():
        start = time.perf_counter()
        sim.step(20000)
        call.append(time.perf_counter() - start)
    worker = threading.Thread(target=step)
    longest = 0.0
    last = time.perf_counter()
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
    longest = max(longest, time.perf_counter() - last)
    worker.join()
    assert sim.time == pytest.approx(20.0, abs=1e-9)
    assert longest < 0.5 * call[0], (longest, call[0])
