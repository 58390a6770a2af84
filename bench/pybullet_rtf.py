#!/usr/bin/python3
"""The bench scenario in PyBullet, for comparison: the Burger URDF on the round track's
walls, 1 kHz physics, a 360-ray scan at 5 Hz, IMU (link state) at 200 Hz, odometry and
joint states at 30 Hz, run as fast as possible. Prints the real-time factor.

Usage: pybullet_rtf.py URDF_FILE WORLD_FILE SIM_SECONDS
"""
import math
import os
import sys
import time
import xml.etree.ElementTree as ET

import pybullet as p

STEP_S = 0.001
RAY_COUNT, RAY_MIN_M, RAY_MAX_M = 360, 0.12, 3.5


def add_walls(world_file):
    """Static boxes of the SDF world (models with a box collision), as PyBullet bodies."""
    for model in ET.parse(world_file).getroot().iter("model"):
        box = model.find("link/collision/geometry/box/size")
        if box is None:
            continue
        x, y, z, _, _, yaw = (float(v) for v in model.find("pose").text.split())
        half = [float(v) / 2 for v in box.text.split()]
        shape = p.createCollisionShape(p.GEOM_BOX, halfExtents=half)
        p.createMultiBody(0, shape, basePosition=[x, y, z],
                          baseOrientation=p.getQuaternionFromEuler([0, 0, yaw]))


def load_quietly(urdf_file):
    """Loads the URDF with PyBullet's importer warnings (written to fd 1) silenced."""
    saved_stdout = os.dup(1)
    with open(os.devnull, "w") as devnull:
        os.dup2(devnull.fileno(), 1)
        try:
            return p.loadURDF(urdf_file, [0, 0, 0], p.getQuaternionFromEuler([0, 0, 1.5675]))
        finally:
            os.dup2(saved_stdout, 1)
            os.close(saved_stdout)


def main():
    urdf_file, world_file, sim_s = sys.argv[1], sys.argv[2], float(sys.argv[3])
    p.connect(p.DIRECT)
    p.setGravity(0, 0, -9.8)
    p.setTimeStep(STEP_S)
    p.createMultiBody(0, p.createCollisionShape(p.GEOM_PLANE))
    add_walls(world_file)
    robot = load_quietly(urdf_file)
    joints = {p.getJointInfo(robot, j)[1].decode(): j for j in range(p.getNumJoints(robot))}
    links = {p.getJointInfo(robot, j)[12].decode(): j for j in range(p.getNumJoints(robot))}
    moving = [j for j in range(p.getNumJoints(robot))
              if p.getJointInfo(robot, j)[2] != p.JOINT_FIXED]
    for name in ("wheel_left_joint", "wheel_right_joint"):
        p.setJointMotorControl2(robot, joints[name], p.VELOCITY_CONTROL, targetVelocity=0,
                                force=10)
    angles = [2 * math.pi * i / RAY_COUNT for i in range(RAY_COUNT)]
    steps = int(round(sim_s / STEP_S))
    start = time.monotonic()
    for step in range(steps):
        p.stepSimulation()
        if step % 200 == 0:
            pos, orn = p.getLinkState(robot, links["base_scan"])[:2]
            yaw = p.getEulerFromQuaternion(orn)[2]
            starts = [[pos[0] + RAY_MIN_M * math.cos(a + yaw), pos[1] + RAY_MIN_M * math.sin(a + yaw),
                       pos[2]] for a in angles]
            ends = [[pos[0] + RAY_MAX_M * math.cos(a + yaw), pos[1] + RAY_MAX_M * math.sin(a + yaw),
                     pos[2]] for a in angles]
            p.rayTestBatch(starts, ends)
        if step % 5 == 0:
            p.getLinkState(robot, links["imu_link"], computeLinkVelocity=1)
        if step % 33 == 0:
            p.getBasePositionAndOrientation(robot)
            p.getBaseVelocity(robot)
            p.getJointStates(robot, moving)
    wall_s = time.monotonic() - start
    print("pybullet real-time factor %.1f (%.1f s sim in %.2f s wall)" % (sim_s / wall_s, sim_s,
                                                                          wall_s))


if __name__ == "__main__":
    main()
