#!/usr/bin/python3
"""The bench scenario in MuJoCo, for comparison: the Burger and the round track's walls
built in MJCF from the same URDF and world files bullet_sim loads, 1 kHz physics, diff
drive by wheel velocity actuators (torque limit and wheel acceleration of the Burger's
plugin), a 360-ray lidar at 5 Hz with mj_multiRay, IMU at 200 Hz, odometry, joint states
and link poses at 30 Hz, the command of bench/sim_rtf.sh. No ROS.

  mujoco_rtf.py URDF WORLD rtf SIM_SECONDS      prints the real-time factor last
  mujoco_rtf.py URDF WORLD camera FRAMES        640x480 frames of the Burger's camera with
                                                the world's lights (MUJOCO_GL=egl), then
                                                depth frames; prints the median ms last
  mujoco_rtf.py URDF TEXTURED_WORLD camera-textured FRAMES
                                                the same colour frames of the round track
                                                that textured_world.py painted, its images
                                                as MuJoCo textures
The camera renders without multisampling, as Gazebo's and bullet_sim's cameras do (MuJoCo's
default of 4 samples costs about 4x per frame on llvmpipe); the sky stays black (no skybox).
Needs the mujoco wheel (bench/compare installs it into build/bench_venv).
"""
import math
import os
import statistics
import sys
import time

import numpy as np

import mujoco
import mjcf_builder
import scenario
import textured_world


def load_model(urdf_file, world_file, textures=None):
    xml = mjcf_builder.build_mjcf(urdf_file, world_file, textures)
    return mujoco.MjModel.from_xml_string(xml)


class Burger:
    """Sensors and diff drive of the robot in a MuJoCo model."""

    def __init__(self, model, data):
        self.m, self.d = model, data
        self.lidar = model.site("base_scan").id
        self.imu = model.site("imu_link").id
        self.free_qpos = model.jnt_qposadr[model.joint("root").id]
        hinge = mujoco.mjtJoint.mjJNT_HINGE
        self.hinges = [j for j in range(model.njnt) if model.jnt_type[j] == hinge]
        self.left = model.actuator("wheel_left_joint").id
        self.right = model.actuator("wheel_right_joint").id
        angles = scenario.ray_angles_rad()
        self.local_dirs = np.array([[math.cos(a), math.sin(a), 0.0] for a in angles])
        self.geomgroup = np.array([1, 0, 0, 0, 0, 0], dtype=np.uint8)  # world geoms only
        self.geomid = np.zeros(scenario.RAY_COUNT, dtype=np.int32)
        self.dist = np.zeros(scenario.RAY_COUNT)
        self.imu_acc = np.zeros(6)
        self.imu_vel = np.zeros(6)
        self.wheel_targets = (0.0, 0.0)

    def scan(self):
        """Ranges as a LaserScan holds them: inf where nothing is hit within range_max."""
        rotation = self.d.site_xmat[self.lidar].reshape(3, 3)
        dirs = (self.local_dirs @ rotation.T).ravel()
        mujoco.mj_multiRay(self.m, self.d, self.d.site_xpos[self.lidar], dirs, self.geomgroup, 1,
                           -1, self.geomid, self.dist, None, scenario.RAY_COUNT,
                           scenario.RAY_MAX_M)
        ranges = self.dist.copy()
        ranges[(ranges < scenario.RAY_MIN_M) | (ranges > scenario.RAY_MAX_M)] = np.inf
        return ranges

    def imu_reading(self):
        mujoco.mj_objectAcceleration(self.m, self.d, mujoco.mjtObj.mjOBJ_SITE, self.imu,
                                     self.imu_acc, 1)
        mujoco.mj_objectVelocity(self.m, self.d, mujoco.mjtObj.mjOBJ_SITE, self.imu,
                                 self.imu_vel, 1)
        return self.d.site_xmat[self.imu].copy(), self.imu_vel[:3].copy(), self.imu_acc[3:].copy()

    def odometry_and_joints(self):
        """What the node publishes at 30 Hz: odometry, joint states, link poses for tf."""
        qpos = self.d.qpos[self.free_qpos:self.free_qpos + 7].copy()
        twist = self.d.qvel[:6].copy()
        joints = [(self.d.qpos[self.m.jnt_qposadr[j]], self.d.qvel[self.m.jnt_dofadr[j]])
                  for j in self.hinges]
        poses = (self.d.xpos.copy(), self.d.xquat.copy())
        return qpos, twist, joints, poses

    def drive(self, linear_mps, angular_radps):
        """One diff-drive update (30 Hz): wheel speeds ramp at the plugin's acceleration."""
        target = scenario.wheel_speeds_radps(linear_mps, angular_radps)
        max_delta = scenario.WHEEL_ACCEL_MPS2 / scenario.WHEEL_RADIUS_M * (
            scenario.ODOM_PERIOD_STEPS * scenario.STEP_S)
        self.wheel_targets = tuple(scenario.ramp(c, t, max_delta)
                                   for c, t in zip(self.wheel_targets, target))
        self.d.ctrl[self.left], self.d.ctrl[self.right] = self.wheel_targets


def next_multiple(step, period):
    return (step // period + 1) * period


def run_rtf(model, sim_s):
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    robot = Burger(model, data)
    scenario.check_spawn_scan(robot.scan(), "mujoco")
    track = scenario.Track()
    steps = int(round(sim_s / scenario.STEP_S))
    start, cpu_start = time.monotonic(), time.process_time()
    step = 0
    while step < steps:
        if step % scenario.ODOM_PERIOD_STEPS == 0:
            robot.drive(scenario.CMD_LINEAR_MPS, scenario.CMD_ANGULAR_RADPS)
            qpos = robot.odometry_and_joints()[0]
            track.add(qpos[0], qpos[1], scenario.yaw_of_quaternion(*qpos[3:7]))
        if step % scenario.LIDAR_PERIOD_STEPS == 0:
            robot.scan()
        if step % scenario.IMU_PERIOD_STEPS == 0:
            robot.imu_reading()
        # Step in C up to the next sensor or drive update (no Python between steps).
        nstep = min(steps, next_multiple(step, scenario.IMU_PERIOD_STEPS),
                    next_multiple(step, scenario.ODOM_PERIOD_STEPS)) - step
        mujoco.mj_step(model, data, nstep)
        step += nstep
    wall_s, cpu_s = time.monotonic() - start, time.process_time() - cpu_start
    track.check(data.time, "mujoco")
    print("mujoco %s: drove %.2f m, turned %.2f rad; sanity checks passed"
          % (mujoco.__version__, track.length_m, track.turned_rad))
    print("process CPU time %.3f s: real-time factor per CPU second %.1f" % (cpu_s, sim_s / cpu_s))
    print("mujoco real-time factor %.1f (%.1f s sim in %.2f s wall)" % (sim_s / wall_s, sim_s,
                                                                      wall_s))


def frame_times_ms(model, frames, depth, textured=False):
    """Renders `frames` camera frames 1/30 s of sim time apart while the robot drives."""
    data = mujoco.MjData(model)
    robot = Burger(model, data)
    times = []
    with mujoco.Renderer(model, 480, 640) as renderer:
        if depth:
            renderer.enable_depth_rendering()
        for frame in range(frames + 1):
            for _ in range(scenario.ODOM_PERIOD_STEPS):
                mujoco.mj_step(model, data)
            robot.drive(scenario.CMD_LINEAR_MPS, scenario.CMD_ANGULAR_RADPS)
            start = time.monotonic()
            renderer.update_scene(data, camera="head")
            image = renderer.render()
            if frame > 0:  # the first frame builds GL state
                times.append(1e3 * (time.monotonic() - start))
            if frame == 1:
                check_image(image, depth, textured)
    return times


def check_image(image, depth, textured=False):
    """Raises unless a frame shows the walls and floor (not a blank or black frame); a
    textured frame must also show its images: many shades of wall and of floor, where the
    plain track's flat faces have a few."""
    if depth:
        finite = image[(image > 0.02) & (image < 100)]
        if finite.size < image.size // 2 or finite.min() > 1.0:
            raise scenario.SanityError("mujoco: the depth frame sees no wall within 1 m")
        return
    pixels = image.reshape(-1, 3).astype(int)
    brown = np.sum((pixels[:, 0] > pixels[:, 2] + 15) & (pixels[:, 1] > pixels[:, 2]))
    grey = np.sum((abs(pixels[:, 0] - pixels[:, 2]) < 10) & (pixels[:, 0] > 40))
    if brown < pixels.shape[0] // 10 or grey < pixels.shape[0] // 10:
        raise scenario.SanityError("mujoco: the camera frame shows %d wall and %d floor pixels "
                                   "of %d" % (brown, grey, pixels.shape[0]))
    if textured:
        scenario.check_textured_frame(pixels, "mujoco")


def run_camera(model, frames):
    info = []
    for depth in (False, True):
        times = frame_times_ms(model, frames, depth)
        info.append(statistics.median(times))
        print("mujoco %s 640x480 %s frame: median %.2f ms, p95 %.2f ms (%d frames)" % (
            mujoco.__version__, "depth" if depth else "rgb", statistics.median(times),
            sorted(times)[int(0.95 * (len(times) - 1))], len(times)))
    print("mujoco camera median %.3f ms depth median %.3f ms" % tuple(info))


def run_textured_camera(model, frames):
    times = frame_times_ms(model, frames, False, textured=True)
    print("mujoco %s 640x480 rgb frame, textured: median %.2f ms, p95 %.2f ms (%d frames)" % (
        mujoco.__version__, statistics.median(times), sorted(times)[int(0.95 * (len(times) - 1))],
        len(times)))
    print("mujoco textured camera median %.3f ms" % statistics.median(times))


def main():
    urdf_file, world_file, mode, amount = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
    textures = textured_world.texture_files(os.path.dirname(world_file)) \
        if mode == "camera-textured" else None
    model = load_model(urdf_file, world_file, textures)
    try:
        if mode == "rtf":
            run_rtf(model, float(amount))
        elif mode == "camera":
            run_camera(model, int(amount))
        elif mode == "camera-textured":
            run_textured_camera(model, int(amount))
        else:
            sys.exit("unknown mode %r: rtf, camera or camera-textured" % mode)
    except scenario.SanityError as error:
        sys.exit("sanity check failed: %s" % error)


if __name__ == "__main__":
    main()
