#!/usr/bin/python3
"""Soak test of bullet_sim_node: the round track as fast as possible for hours of sim time.

A seeded random-walk command drives the Burger (a new command each sim second: speed and
turn rate take a random step within the real Burger's limits). Every sim second it checks
that the robot is inside the track (inside the walls' bounding box and no nearer than
MIN_WALL_CLEARANCE_M to any wall's centre line: it has not gone through a wall), upright
(roll and pitch under 45 degrees), that /clock never went back, and it samples the node's
resident memory. At the end memory after warm-up may have grown by at most 5 %.

Usage: bench/soak.py [--sim-hours H] [--seed N] [--port P]   (needs a built devel/ space)
Prints one line per sim minute and a summary; exits 1 when a check failed.
"""
import argparse
import atexit
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'src', 'turtlebot3_gazebo', 'scripts'))
from make_round_track_world import WALLS_X_Y_YAW_LENGTH, WALL_THICKNESS_M  # noqa: E402

MAX_LINEAR_MPS, MAX_ANGULAR_RADPS = 0.22, 2.84  # the real Burger's limits
# base_footprint is 0.038 m behind the Burger's front face; touching a wall it is
# 0.038 + 0.0075 m from the wall's centre line. Nearer than this, it went into the wall.
MIN_WALL_CLEARANCE_M = 0.03
MAX_TILT_RAD = math.radians(45)
WARMUP_SIM_S = 120.0
MAX_MEMORY_GROWTH = 0.05


def wall_segments():
    """Centre lines of the walls: length along each wall's local y."""
    for x, y, yaw, length in WALLS_X_Y_YAW_LENGTH:
        dx, dy = -math.sin(yaw) * length / 2, math.cos(yaw) * length / 2
        yield (x - dx, y - dy), (x + dx, y + dy)


def distance_to_segment(p, a, b):
    ax, ay = a
    bx, by = b
    vx, vy = bx - ax, by - ay
    t = max(0.0, min(1.0, ((p[0] - ax) * vx + (p[1] - ay) * vy) / (vx * vx + vy * vy)))
    return math.hypot(p[0] - ax - t * vx, p[1] - ay - t * vy)


def track_bounds():
    xs = [c[0] for s in wall_segments() for c in s]
    ys = [c[1] for s in wall_segments() for c in s]
    return min(xs), max(xs), min(ys), max(ys)


def rss_kb(pid):
    with open('/proc/%d/status' % pid) as status:
        for line in status:
            if line.startswith('VmRSS:'):
                return int(line.split()[1])
    return 0


class Soak(object):
    def __init__(self, args, node_pid):
        import rospy
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        from rosgraph_msgs.msg import Clock
        self.rospy, self.Twist = rospy, Twist
        self.args, self.node_pid = args, node_pid
        self.rng = random.Random(args.seed)
        self.lock = threading.Lock()
        self.clock_s, self.clock_regressions, self.odom = 0.0, 0, None
        self.cmd = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
        rospy.Subscriber('/clock', Clock, self.on_clock, queue_size=1000)
        rospy.Subscriber('/odom', Odometry, self.on_odom, queue_size=1)
        self.segments = list(wall_segments())
        self.bounds = track_bounds()
        self.failures, self.min_clearance, self.max_tilt = [], float('inf'), 0.0
        self.rss = []
        self.linear, self.angular = 0.1, 0.0

    def start(self):
        """Unpauses the simulation once it listens to the commands."""
        from std_srvs.srv import Empty
        deadline = time.monotonic() + 30
        while self.cmd.get_num_connections() == 0:
            if time.monotonic() > deadline:
                raise RuntimeError('bullet_sim_node never subscribed to /cmd_vel')
            time.sleep(0.01)
        self.next_command()
        self.rospy.wait_for_service('/gazebo/unpause_physics', 30)
        self.rospy.ServiceProxy('/gazebo/unpause_physics', Empty)()

    def on_clock(self, msg):
        t = msg.clock.to_sec()
        with self.lock:
            if t < self.clock_s:
                self.clock_regressions += 1
            self.clock_s = t

    def on_odom(self, msg):
        with self.lock:
            self.odom = msg

    def next_command(self):
        self.linear = min(MAX_LINEAR_MPS, max(-0.1, self.linear + self.rng.gauss(0, 0.05)))
        self.angular = min(MAX_ANGULAR_RADPS,
                           max(-MAX_ANGULAR_RADPS, self.angular + self.rng.gauss(0, 0.8)))
        command = self.Twist()
        command.linear.x, command.angular.z = self.linear, self.angular
        self.cmd.publish(command)

    def check(self, sim_s):
        with self.lock:
            odom = self.odom
        if odom is None:
            return
        p = odom.pose.pose.position
        q = odom.pose.pose.orientation
        roll = math.atan2(2 * (q.w * q.x + q.y * q.z), 1 - 2 * (q.x * q.x + q.y * q.y))
        pitch = math.asin(max(-1.0, min(1.0, 2 * (q.w * q.y - q.z * q.x))))
        clearance = min(distance_to_segment((p.x, p.y), a, b) for a, b in self.segments)
        self.min_clearance = min(self.min_clearance, clearance)
        self.max_tilt = max(self.max_tilt, abs(roll), abs(pitch))
        x0, x1, y0, y1 = self.bounds
        if not (x0 < p.x < x1 and y0 < p.y < y1):
            self.failures.append('%.0f s: robot at (%.3f, %.3f) is outside the track' %
                                 (sim_s, p.x, p.y))
        if clearance < MIN_WALL_CLEARANCE_M:
            self.failures.append('%.0f s: robot at (%.3f, %.3f) is %.3f m from a wall centre '
                                 'line: inside the wall' % (sim_s, p.x, p.y, clearance))
        if max(abs(roll), abs(pitch)) > MAX_TILT_RAD:
            self.failures.append('%.0f s: robot tipped over (roll %.2f, pitch %.2f rad)' %
                                 (sim_s, roll, pitch))

    def run(self):
        duration_s = self.args.sim_hours * 3600.0
        wall_start, next_check = time.monotonic(), 1.0
        while next_check <= duration_s and not self.rospy.is_shutdown():
            with self.lock:
                now = self.clock_s
            if now < next_check:
                time.sleep(0.0005)
                continue
            self.check(next_check)
            self.next_command()
            self.rss.append((next_check, rss_kb(self.node_pid)))
            if int(next_check) % 60 == 0:
                print('sim %6.0f s  wall %6.1f s  x %.2f y %.2f  rss %d kB' % (
                    next_check, time.monotonic() - wall_start, self.odom.pose.pose.position.x,
                    self.odom.pose.pose.position.y, self.rss[-1][1]), flush=True)
            if len(self.failures) > 20:
                break
            next_check += 1.0
        return time.monotonic() - wall_start

    def report(self, wall_s):
        sim_s = self.rss[-1][0] if self.rss else 0.0
        warm = [kb for t, kb in self.rss if t >= WARMUP_SIM_S]
        growth = (warm[-1] - warm[0]) / float(warm[0]) if len(warm) > 1 else 0.0
        if growth > MAX_MEMORY_GROWTH:
            self.failures.append('resident memory grew %.1f %% after warm-up (%d -> %d kB)' %
                                 (100 * growth, warm[0], warm[-1]))
        if self.clock_regressions:
            self.failures.append('/clock went back %d times' % self.clock_regressions)
        print('soak: %.0f s of sim time in %.0f s of wall time (real-time factor %.0f), seed %d'
              % (sim_s, wall_s, sim_s / wall_s if wall_s else 0, self.args.seed))
        print('soak: nearest to a wall centre line %.3f m (limit %.3f), largest tilt %.1f deg, '
              '/clock regressions %d' % (self.min_clearance, MIN_WALL_CLEARANCE_M,
                                         math.degrees(self.max_tilt), self.clock_regressions))
        if warm:
            print('soak: node resident memory %d kB at %.0f s, %d kB at the end (%+.1f %%)' %
                  (warm[0], WARMUP_SIM_S, warm[-1], 100 * growth))
        for failure in self.failures:
            print('soak: FAILED: ' + failure)
        return 0 if not self.failures else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--sim-hours', type=float, default=2.0)
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--port', type=int, default=11463)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix='soak_')
    atexit.register(shutil.rmtree, work, ignore_errors=True)
    env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % args.port,
               ROS_HOSTNAME='localhost', ROS_HOME=os.path.join(work, 'ros_home'))
    os.environ.update(env)
    procs = []
    try:
        procs.append(subprocess.Popen(['roscore', '-p', str(args.port)],
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        urdf = subprocess.run(['rosrun', 'xacro', 'xacro', os.path.join(
            ROOT, 'turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro')],
            stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
        import rosgraph
        deadline = time.monotonic() + 30
        while not rosgraph.is_master_online():
            if time.monotonic() > deadline:
                raise RuntimeError('roscore did not start on port %d' % args.port)
            time.sleep(0.1)
        import rospy
        rospy.set_param('/robot_description', urdf)
        node = subprocess.Popen(['rosrun', 'bullet_sim', 'bullet_sim_node',
                                 '_world_file:=' + os.path.join(
                                     ROOT, 'src/turtlebot3_gazebo/worlds/roundTrack.world'),
                                 '_real_time_factor:=0', '_robot_name:=turtlebot3_burger',
                                 '_spawn_yaw:=1.5675', '_seed:=%d' % args.seed,
                                 '_paused:=true'],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        procs.append(node)
        rospy.init_node('soak', disable_signals=True)
        soak = Soak(args, node.pid)  # rosrun execs the node: same process
        soak.start()
        return soak.report(soak.run())
    finally:
        for proc in reversed(procs):
            proc.terminate()
            proc.wait()


if __name__ == '__main__':
    sys.exit(main())
