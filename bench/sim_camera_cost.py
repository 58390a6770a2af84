#!/usr/bin/python3
"""Camera cost inside bullet_sim_node: the round-track Burger, driving a slow circle, run as fast as possible,
first with nobody watching the camera, then with a subscriber on /camera/image_raw.
Prints the real-time factor of both phases, the image rate in sim time, and the node's
wall time per published frame (render + message + send), as the difference of the two
phases divided by the frames sent.

Usage: bench/sim_camera_cost.py [SIM_SECONDS_PER_PHASE]   (default 10; needs a built
       devel space: BENCH_DEVEL=/path/to/devel, else ./devel; BENCH_ROS_PORT, default 11458)
"""
import atexit
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DRIVE_MPS, DRIVE_RADPS = 0.1, 0.3  # a 0.33 m radius circle that stays in the west lane


def ros_env(devel, port):
    """The environment of `source devel/setup.bash` with our own master."""
    out = subprocess.run(["bash", "-c", "source %s/setup.bash && env -0" % devel],
                         check=True, stdout=subprocess.PIPE).stdout
    env = dict(item.split("=", 1) for item in out.decode().split("\0") if "=" in item)
    env["ROS_MASTER_URI"] = "http://localhost:%d" % port
    env["PATH"] = "/usr/bin:/bin:" + env.get("PATH", "")
    return env


class Probe:
    """Follows /clock and counts images; run in this process once rospy is importable."""

    def __init__(self, rospy, clock_type):
        self.rospy = rospy
        self.lock = threading.Lock()
        self.sim_s = 0.0
        self.images = []
        rospy.Subscriber("/clock", clock_type, self.on_clock, queue_size=10)

    def on_clock(self, msg):
        with self.lock:
            self.sim_s = msg.clock.to_sec()

    def on_image(self, msg):
        with self.lock:
            self.images.append(msg.header.stamp.to_sec())

    def now(self):
        with self.lock:
            return self.sim_s

    def measure(self, sim_seconds):
        """Wall seconds the simulation needs for `sim_seconds`, and the sim window."""
        start_sim = self.now()
        start_wall = time.monotonic()
        while self.now() < start_sim + sim_seconds:
            if time.monotonic() - start_wall > 600:
                raise RuntimeError("the simulation does not advance")
            time.sleep(0.005)
        return time.monotonic() - start_wall, self.now() - start_sim


def main():
    sim_seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 10.0
    devel = os.environ.get("BENCH_DEVEL", os.path.join(ROOT, "devel"))
    port = int(os.environ.get("BENCH_ROS_PORT", "11458"))
    env = ros_env(devel, port)
    for key, value in env.items():
        os.environ[key] = value
    sys.path[:0] = [p for p in env.get("PYTHONPATH", "").split(":") if p]
    work = tempfile.mkdtemp(prefix="bench_camera_cost_")
    atexit.register(shutil.rmtree, work, ignore_errors=True)
    procs = []
    try:
        procs.append(subprocess.Popen(["roscore", "-p", str(port)], env=env,
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        import rospy
        from rosgraph_msgs.msg import Clock
        from geometry_msgs.msg import Twist
        from sensor_msgs.msg import Image
        deadline = time.monotonic() + 30
        while subprocess.run(["rosparam", "list"], env=env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL).returncode != 0:
            if time.monotonic() > deadline:
                raise RuntimeError("roscore did not start on port %d" % port)
            time.sleep(0.2)
        urdf = os.path.join(work, "burger.urdf")
        with open(urdf, "w") as f:
            subprocess.run(["rosrun", "xacro", "xacro", os.path.join(
                ROOT, "turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro")],
                env=env, check=True, stdout=f)
        subprocess.run(["rosparam", "set", "robot_description", "-t", urdf], env=env, check=True)
        world = os.path.join(ROOT, "src/turtlebot3_gazebo/worlds/roundTrack.world")
        procs.append(subprocess.Popen(
            ["rosrun", "bullet_sim", "bullet_sim_node", "_world_file:=" + world,
             "_real_time_factor:=0", "_robot_name:=turtlebot3_burger", "_spawn_yaw:=1.5675"], env=env,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        rospy.init_node("camera_cost_bench", anonymous=True, disable_signals=True)
        # Drive a slow circle in the lane: a robot at rest sleeps and costs nothing.
        drive = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        command = Twist()
        command.linear.x, command.angular.z = DRIVE_MPS, DRIVE_RADPS
        drive.publish(command)
        deadline = time.monotonic() + 30
        while drive.get_num_connections() == 0:
            if time.monotonic() > deadline:
                raise RuntimeError("bullet_sim_node did not subscribe to /cmd_vel")
            time.sleep(0.05)
        time.sleep(0.5)  # the latched command reaches the node
        probe = Probe(rospy, Clock)
        while probe.now() < 1.0:  # warm-up
            time.sleep(0.05)
        wall_plain, sim_plain = probe.measure(sim_seconds)
        sub = rospy.Subscriber("/camera/image_raw", Image, probe.on_image, queue_size=1,
                               buff_size=1 << 24)
        while not probe.images:
            time.sleep(0.01)
        first = probe.now()
        wall_cam, sim_cam = probe.measure(sim_seconds)
        sub.unregister()
        frames = sim_cam * 30.0
        got = [t for t in probe.images if first <= t <= first + sim_cam]
        print("bullet_sim_node, round track, %.0f s sim per phase, as fast as possible:"
              % sim_seconds)
        print("  without camera subscriber: real-time factor %.1f" % (sim_plain / wall_plain))
        print("  with /camera/image_raw subscribed: real-time factor %.1f" % (sim_cam / wall_cam))
        print("  images received: %d in %.1f s sim (%.1f Hz sim; the subscriber may drop some)"
              % (len(got), sim_cam, len(got) / sim_cam))
        per_frame_ms = 1e3 * (wall_cam / sim_cam - wall_plain / sim_plain) / 30.0
        print("  node wall time per camera frame (30 Hz sim): %.2f ms" % per_frame_ms)
    finally:
        for proc in reversed(procs):
            proc.terminate()
            proc.wait(timeout=20)


if __name__ == "__main__":
    main()
