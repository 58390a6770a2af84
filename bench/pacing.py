#!/usr/bin/python3
"""Pacing at real_time_factor 1: starts `roslaunch turtlebot3_gazebo
roundTrack_simulation.launch` (gui:=true under Xvfb, so RViz runs with the launch's view:
robot, laser scan, odometry and the camera image), subscribes to the camera too, sets the
Burger driving a slow circle, waits 3 s of sim time, then compares /clock with the wall
clock over a window of wall time. Prints the sim/wall ratio, its deviation from 1 in
percent, the largest lag of sim time behind the wall clock within the window, the camera's
frame rate and whether RViz ran all along; the deviation line last.

Usage: pacing.py [--seconds 60] [--no-gui]   (BENCH_ROS_PORT, default 11466)
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import threading
import time

import ros_bench


class Samples:
    """(wall, sim) pairs of every /clock message, and camera frames, from rospy's threads."""

    def __init__(self):
        self.lock = threading.Lock()
        self.clock = []
        self.frames = []
        self.recording = False

    def on_clock(self, msg):
        now = time.monotonic()
        with self.lock:
            if self.recording:
                self.clock.append((now, msg.clock.to_sec()))
            else:
                self.clock[:] = [(now, msg.clock.to_sec())]

    def on_image(self, _msg):
        now = time.monotonic()
        with self.lock:
            if self.recording:
                self.frames.append(now)

    def latest_sim(self):
        with self.lock:
            return self.clock[-1][1] if self.clock else 0.0


def largest_lag_s(clock):
    """How far sim time fell behind the wall clock at worst, both measured from the start."""
    wall0, sim0 = clock[0]
    return max((wall - wall0) - (sim - sim0) for wall, sim in clock)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--no-gui", action="store_true", help="without RViz")
    args = parser.parse_args()
    gui = not args.no_gui
    if gui and not shutil.which("xvfb-run"):
        sys.exit("pacing: xvfb-run is missing (make setup installs it)")
    port = int(os.environ.get("BENCH_ROS_PORT", "11466"))
    env = ros_bench.ros_env(port)
    ros_bench.adopt_env(env)
    import rospy
    from geometry_msgs.msg import Twist
    from rosgraph_msgs.msg import Clock
    from sensor_msgs.msg import Image
    samples = Samples()
    with ros_bench.Processes() as procs:
        ros_bench.start_master(procs, env, port)
        launch = ["roslaunch", "-p", str(port), "turtlebot3_gazebo",
                  "roundTrack_simulation.launch", "gui:=%s" % str(gui).lower()]
        if gui:
            launch = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"] + launch
        # A session of its own: xvfb-run does not pass SIGINT on to roslaunch, so the
        # whole group gets it at the end (roslaunch then stops RViz and the nodes).
        roslaunch = procs.start(launch, env, start_new_session=True)
        rospy.init_node("bench_pacing", anonymous=True, disable_signals=True)
        rospy.Subscriber("/clock", Clock, samples.on_clock, queue_size=100)
        rospy.Subscriber("/camera/image_raw", Image, samples.on_image, queue_size=1,
                         buff_size=2 ** 22)
        cmd = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        ros_bench.wait_for(lambda: samples.latest_sim() > 1.0, "/clock past 1 s", timeout_s=60)
        twist = Twist()
        twist.linear.x, twist.angular.z = 0.1, 0.3
        cmd.publish(twist)
        ros_bench.wait_for(lambda: samples.latest_sim() > 3.0, "/clock past 3 s", timeout_s=60)
        rviz = ros_bench.process_named(ros_bench.descendants(roslaunch.pid), "rviz")
        if gui and rviz is None:
            sys.exit("pacing: RViz is not running under roslaunch")
        with samples.lock:
            samples.recording = True
            samples.clock[:] = samples.clock[-1:]
        time.sleep(args.seconds)  # the measured window of wall time
        with samples.lock:
            samples.recording = False
            clock, frames = list(samples.clock), list(samples.frames)
        rviz_alive = gui and ros_bench.process_named(
            ros_bench.descendants(roslaunch.pid), "rviz") == rviz
        rospy.signal_shutdown("measured")
        os.killpg(roslaunch.pid, signal.SIGINT)
        try:
            roslaunch.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(roslaunch.pid, signal.SIGKILL)
    if len(clock) < 2 or len(frames) < 2:
        sys.exit("pacing: %d /clock messages and %d camera frames in the window"
                 % (len(clock), len(frames)))
    wall_s, sim_s = clock[-1][0] - clock[0][0], clock[-1][1] - clock[0][1]
    ratio = sim_s / wall_s
    print("window %.1f s wall, %.3f s sim, %d /clock messages" % (wall_s, sim_s, len(clock)))
    print("camera %.1f frames per wall second; RViz %s" % (
        (len(frames) - 1) / (frames[-1] - frames[0]),
        "ran all along" if rviz_alive else ("not started" if not gui else "stopped")))
    print("largest lag of sim time behind the wall clock %.1f ms" % (1e3 * largest_lag_s(clock)))
    print("sim/wall %.5f, deviation %.3f %%" % (ratio, 100.0 * abs(ratio - 1.0)))


if __name__ == "__main__":
    main()
