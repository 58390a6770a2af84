#!/usr/bin/python3
"""The bench scenario in PyBullet, for comparison: the Burger URDF on the round track's
walls, 1 kHz physics, the command of bench/sim_rtf.sh through wheel velocity motors (torque
limit and wheel acceleration of the Burger's plugin), a 360-ray scan at 5 Hz, IMU (link
state) at 200 Hz, odometry and joint states at 30 Hz, run as fast as possible, no ROS.
Checks its first scan against the wall table and the distance driven (bench/scenario.py),
then prints the real-time factor last.

Usage: pybullet_rtf.py URDF_FILE WORLD_FILE SIM_SECONDS
"""
import math
import os
import sys
import time

import pybullet as p

import scenario


def add_walls(world_file):
    """The world's colliding static boxes as PyBullet bodies."""
    for _, (x, y, z, yaw), size, _, collides in scenario.read_world(world_file):
        if collides:
            shape = p.createCollisionShape(p.GEOM_BOX, halfExtents=[s / 2 for s in size])
            p.createMultiBody(0, shape, basePosition=[x, y, z],
                              baseOrientation=p.getQuaternionFromEuler([0, 0, yaw]))


def load_quietly(urdf_file):
    """Loads the URDF with PyBullet's importer warnings (written to fd 1) silenced."""
    saved_stdout = os.dup(1)
    with open(os.devnull, "w") as devnull:
        os.dup2(devnull.fileno(), 1)
        try:
            return p.loadURDF(urdf_file, [0, 0, 0],
                              p.getQuaternionFromEuler([0, 0, scenario.SPAWN_YAW_RAD]))
        finally:
            os.dup2(saved_stdout, 1)
            os.close(saved_stdout)


class Burger:
    """Sensors and diff drive of the robot in PyBullet."""

    def __init__(self, robot):
        self.robot = robot
        count = p.getNumJoints(robot)
        self.joints = {p.getJointInfo(robot, j)[1].decode(): j for j in range(count)}
        self.links = {p.getJointInfo(robot, j)[12].decode(): j for j in range(count)}
        self.moving = [j for j in range(count) if p.getJointInfo(robot, j)[2] != p.JOINT_FIXED]
        self.angles = scenario.ray_angles_rad()
        self.wheel_targets = (0.0, 0.0)

    def scan(self):
        pos, orn = p.getLinkState(self.robot, self.links["base_scan"])[:2]
        yaw = p.getEulerFromQuaternion(orn)[2]
        lo, hi = scenario.RAY_MIN_M, scenario.RAY_MAX_M
        dirs = [(math.cos(a + yaw), math.sin(a + yaw)) for a in self.angles]
        starts = [[pos[0] + lo * c, pos[1] + lo * s, pos[2]] for c, s in dirs]
        ends = [[pos[0] + hi * c, pos[1] + hi * s, pos[2]] for c, s in dirs]
        return [lo + hit[2] * (hi - lo) if hit[0] >= 0 else math.inf
                for hit in p.rayTestBatch(starts, ends)]

    def drive(self, linear_mps, angular_radps):
        """One diff-drive update (30 Hz): wheel speeds ramp at the plugin's acceleration."""
        target = scenario.wheel_speeds_radps(linear_mps, angular_radps)
        max_delta = scenario.WHEEL_ACCEL_MPS2 / scenario.WHEEL_RADIUS_M * (
            scenario.ODOM_PERIOD_STEPS * scenario.STEP_S)
        self.wheel_targets = tuple(scenario.ramp(c, t, max_delta)
                                   for c, t in zip(self.wheel_targets, target))
        for name, speed in zip(("wheel_left_joint", "wheel_right_joint"), self.wheel_targets):
            p.setJointMotorControl2(self.robot, self.joints[name], p.VELOCITY_CONTROL,
                                    targetVelocity=speed, force=scenario.WHEEL_TORQUE_NM)

    def odometry_and_joints(self):
        pos, orn = p.getBasePositionAndOrientation(self.robot)
        p.getBaseVelocity(self.robot)
        p.getJointStates(self.robot, self.moving)
        return pos, p.getEulerFromQuaternion(orn)[2]


def main():
    urdf_file, world_file, sim_s = sys.argv[1], sys.argv[2], float(sys.argv[3])
    p.connect(p.DIRECT)
    p.setGravity(0, 0, -9.8)
    p.setTimeStep(scenario.STEP_S)
    p.createMultiBody(0, p.createCollisionShape(p.GEOM_PLANE))
    add_walls(world_file)
    robot = Burger(load_quietly(urdf_file))
    try:
        scenario.check_spawn_scan(robot.scan(), "pybullet")
        track = scenario.Track()
        steps = int(round(sim_s / scenario.STEP_S))
        start, cpu_start = time.monotonic(), time.process_time()
        for step in range(steps):
            if step % scenario.ODOM_PERIOD_STEPS == 0:
                robot.drive(scenario.CMD_LINEAR_MPS, scenario.CMD_ANGULAR_RADPS)
                (x, y, _), yaw = robot.odometry_and_joints()
                track.add(x, y, yaw)
            if step % scenario.LIDAR_PERIOD_STEPS == 0:
                robot.scan()
            if step % scenario.IMU_PERIOD_STEPS == 0:
                p.getLinkState(robot.robot, robot.links["imu_link"], computeLinkVelocity=1)
            p.stepSimulation()
        wall_s, cpu_s = time.monotonic() - start, time.process_time() - cpu_start
        track.check(sim_s, "pybullet")
    except scenario.SanityError as error:
        sys.exit("sanity check failed: %s" % error)
    print("pybullet: drove %.2f m, turned %.2f rad; sanity checks passed"
          % (track.length_m, track.turned_rad))
    print("process CPU time %.3f s: real-time factor per CPU second %.1f" % (cpu_s, sim_s / cpu_s))
    print("pybullet real-time factor %.1f (%.1f s sim in %.2f s wall)" % (sim_s / wall_s, sim_s,
                                                                          wall_s))


if __name__ == "__main__":
    main()
