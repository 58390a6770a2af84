#!/usr/bin/python3
"""ROBOTIS's AutoRace lane follower on the 2020 course, frame by frame in sim time.

Run by run_autorace.py against a running turtlebot3_autorace_2020.launch (the master in
ROS_MASTER_URI): `lane_following.py --mode lane|control --figures FILE`. It pauses the
simulator, resets it (the robot at the launch's spawn, sim time 0), then, by mode:
- `lane`: starts the four launch files a user starts (intrinsic and extrinsic camera
  calibration, detect_lane, control_lane) and steps the simulator one camera frame at a time,
  each frame carried through the whole chain (image_proc, image_projection,
  image_compensation, detect_lane, control_lane) before the next: the run does not depend on
  how fast this machine is. Within --sim-limit (90 s) the robot must reach the end of the first
  left turn (x in [1.63, 1.87], y >= -1.1), its centre never closer than --min-clearance (0.04 m) to
  a white or yellow line of the course texture (course_lines: from the files, never from the
  simulator), /detect/lane at >= 5 Hz of sim time.
- `control`: a constant forward command of control_lane's top speed (0.05 m/s) and nothing
  else: the robot must cross the white line at the first corner (its centre on a white
  texel), which shows that the line check sees the lines.
Figures go to the JSON file of --figures.
"""
import argparse
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rosgraph
import rospkg
import rospy
from bullet_sim.srv import StepSimulation
from gazebo_msgs.srv import GetModelState, GetPhysicsProperties
from geometry_msgs.msg import Twist
from sensor_msgs.msg import Image
from std_msgs.msg import Float64
from std_srvs.srv import Empty

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import course_lines  # noqa: E402

ROBOT = 'autorace'  # the launch's -model name
SPAWN = (0.8, -1.747)  # the launch's x_pos, y_pos
GOAL_X, GOAL_MIN_Y = (1.63, 1.87), -1.1
MIN_RATE_HZ = 5.0
FORWARD_M_S = 0.05  # control_lane's top speed: min(MAX_VEL..., 0.05)
PIPELINE = [('turtlebot3_autorace_camera', 'intrinsic_camera_calibration.launch'),
            ('turtlebot3_autorace_camera', 'extrinsic_camera_calibration.launch'),
            ('turtlebot3_autorace_detect', 'detect_lane.launch'),
            ('turtlebot3_autorace_driving', 'turtlebot3_autorace_control_lane.launch')]
# Each link of the chain: (topic, who must publish it, who must subscribe, what is missing).
# image_proc's nodelets advertise at load and subscribe only once their outputs are read.
CHAIN = [
    ('/camera/image_rect_color', 'image_proc', None,
     'image_proc loaded no nodelet (Debian: libimage-proc-dev)'),
    ('/camera/image_rect_color/compressed', 'image_proc', 'image_projection',
     'image_proc offers no compressed transport: compressed_image_transport is not built'),
    ('/camera/image_projected/compressed', 'image_projection', 'image_compensation_projection', ''),
    ('/camera/image_projected_compensated', 'image_compensation_projection', 'detect_lane', ''),
    ('/detect/lane', 'detect_lane', 'control_lane', ''),
    ('/cmd_vel', 'control_lane', 'gazebo', '')]
# detect_lane handles one frame in three (its counter: "set to 1/3 (10fps)"): the 3rd,
# 6th, ... frame it receives (measured); the others it drops at once.
DETECT_EVERY = 3
FIGURES = {}
OPTIONS = argparse.Namespace(mode='lane', figures='', logs='', sim_limit=90.0,
                             min_clearance=0.04)


def wait(condition, timeout_wall_s, what):
    end = time.monotonic() + timeout_wall_s
    while not condition():
        if time.monotonic() > end or rospy.is_shutdown():
            raise AssertionError('timed out after %.0f s waiting for %s' % (timeout_wall_s, what))
        time.sleep(0.002)


class Counter:
    def __init__(self, topic, kind):
        self.count = 0
        rospy.Subscriber(topic, kind, self.on_message, queue_size=100)

    def on_message(self, _):
        self.count += 1


class TestLaneFollowing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('autorace_lane_following')
        cls.mode = OPTIONS.mode
        cls.sim_limit_s = OPTIONS.sim_limit
        cls.min_clearance_m = OPTIONS.min_clearance
        gazebo = rospkg.RosPack().get_path('turtlebot3_gazebo')
        cls.lines = course_lines.CourseLines(
            os.path.join(gazebo, 'worlds', 'turtlebot3_autorace_2020.world'),
            [os.path.join(gazebo, 'models')], 'model://turtlebot3_autorace_2020/course')
        rospy.wait_for_service('/gazebo/step_simulation', 120)
        cls.step = rospy.ServiceProxy('/gazebo/step_simulation', StepSimulation, persistent=True)
        cls.get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState,
                                           persistent=True)
        wait(lambda: cls.get_state(ROBOT, '').success, 120, 'the robot %s' % ROBOT)
        rospy.ServiceProxy('/gazebo/pause_physics', Empty)()
        rospy.ServiceProxy('/gazebo/reset_simulation', Empty)()
        cls.dt_s = rospy.ServiceProxy('/gazebo/get_physics_properties',
                                      GetPhysicsProperties)().time_step
        cls.processes = []
        cls.logs = OPTIONS.logs or tempfile.mkdtemp(prefix='autorace_lane_')

    @classmethod
    def tearDownClass(cls):
        for process in cls.processes:
            process.send_signal(signal.SIGINT)
        for process in cls.processes:
            try:
                process.wait(30)
            except subprocess.TimeoutExpired:
                process.kill()
        if OPTIONS.figures:
            with open(OPTIONS.figures, 'w') as f:
                json.dump(FIGURES, f, indent=1)

    def pose(self):
        state = self.get_state(ROBOT, '')
        return state.pose.position.x, state.pose.position.y

    def clearance(self, x, y):
        return {p: self.lines.distance(p, x, y) for p in ('white', 'yellow')}

    def start_pipeline(self):
        for package, launch in PIPELINE:
            log = open(os.path.join(self.logs, launch + '.log'), 'w')
            self.processes.append(subprocess.Popen(['roslaunch', package, launch],
                                                   stdout=log, stderr=subprocess.STDOUT))
        master = rosgraph.Master('/autorace_lane_following')

        def missing():
            publishers, subscribers, _ = master.getSystemState()
            pubs, subs = dict(publishers), dict(subscribers)
            for topic, publisher, subscriber, hint in CHAIN:
                if publisher and not any(n.endswith('/' + publisher)
                                         for n in pubs.get(topic, [])):
                    return 'no %s publishing %s%s' % (publisher, topic, hint and ': ' + hint)
                if subscriber and not any(n.endswith('/' + subscriber)
                                          for n in subs.get(topic, [])):
                    return 'no %s subscribing to %s%s' % (subscriber, topic, hint and ': ' + hint)
            return None
        end = time.monotonic() + 180
        while missing() and time.monotonic() < end:
            time.sleep(0.5)
        self.assertIsNone(missing(), 'the AutoRace chain is incomplete after 180 s (logs: %s)'
                          % self.logs)

    def steps_to_next_frame(self, frames, now_steps):
        """Physics steps from now to the camera's next frame: frame n falls on the first
        step whose period ends, ceil(n / (rate dt)), counted from the reset."""
        due = math.ceil((frames + 1) / (30.0 * self.dt_s) - 1e-9)
        return max(1, due - now_steps)

    def test_lane_following(self):
        x, y = self.pose()
        FIGURES['spawn'] = [round(x, 4), round(y, 4)]
        self.assertAlmostEqual(x, SPAWN[0], delta=0.01)
        self.assertAlmostEqual(y, SPAWN[1], delta=0.01)
        # the lines as the files place them: the spawn in the middle of the lane
        start = self.clearance(x, y)
        FIGURES['spawn_clearance_m'] = {k: round(v, 4) for k, v in start.items()}
        self.assertGreater(min(start.values()), 0.08, start)
        if self.mode == 'lane':
            self.drive_lane()
        else:
            self.drive_forward()

    def drive_lane(self):
        camera = Counter('/camera/image', Image)
        detect_input = Counter('/camera/image_projected_compensated', Image)
        lane = Counter('/detect/lane', Float64)
        commands = Counter('/cmd_vel', Twist)
        self.start_pipeline()
        wall_start = time.monotonic()
        now_steps, trace, reached = 0, [], None
        closest = {'white': math.inf, 'yellow': math.inf}
        while now_steps * self.dt_s < self.sim_limit_s and reached is None:
            frames = camera.count
            n = self.steps_to_next_frame(frames, now_steps)
            self.step(n)
            now_steps += n
            wait(lambda: camera.count > frames, 60, 'camera frame %d' % (frames + 1))
            self.assertEqual(camera.count, frames + 1, 'two frames in one step')
            wait(lambda: detect_input.count >= camera.count, 60,
                 'frame %d through image_proc, image_projection and image_compensation'
                 % camera.count)
            if detect_input.count % DETECT_EVERY == 0:
                expected = detect_input.count // DETECT_EVERY
                wait(lambda: lane.count >= expected and commands.count >= expected, 60,
                     '/detect/lane and /cmd_vel for frame %d (detect_lane raising on every '
                     'frame? np.int: README, AutoRace step 1; logs: %s)'
                     % (detect_input.count, self.logs))
            x, y = self.pose()
            for paint, d in self.clearance(x, y).items():
                closest[paint] = min(closest[paint], d)
            trace.append([round(now_steps * self.dt_s, 3), round(x, 4), round(y, 4)])
            if GOAL_X[0] <= x <= GOAL_X[1] and y >= GOAL_MIN_Y:
                reached = now_steps * self.dt_s
        sim_s = now_steps * self.dt_s
        FIGURES.update({
            'mode': 'lane', 'reached_sim_s': reached, 'sim_s': round(sim_s, 3),
            'wall_s': round(time.monotonic() - wall_start, 1), 'frames': camera.count,
            'detect_lane_msgs': lane.count, 'detect_lane_hz': round(lane.count / sim_s, 2),
            'cmd_vel_msgs': commands.count,
            'closest_m': {k: round(v, 4) for k, v in closest.items()},
            'end': trace[-1], 'trace': trace[::30]})
        print('figures: %s' % {k: v for k, v in FIGURES.items() if k != 'trace'})
        self.assertGreaterEqual(lane.count / sim_s, MIN_RATE_HZ,
                                '/detect/lane at %.2f Hz of sim time (detect_lane log: %s)'
                                % (lane.count / sim_s, self.logs))
        self.assertIsNotNone(reached, 'the end of the first left turn not reached in %.0f s: '
                             'last pose %s' % (self.sim_limit_s, trace[-1]))
        for paint, d in closest.items():
            self.assertGreaterEqual(d, self.min_clearance_m,
                                    'the robot came %.3f m from the %s line' % (d, paint))

    def drive_forward(self):
        command = rospy.Publisher('/cmd_vel', Twist, queue_size=1, latch=True)
        twist = Twist()
        twist.linear.x = FORWARD_M_S
        command.publish(twist)
        # latched: sent to the simulator as soon as its connection is made, before any step
        wait(lambda: command.get_num_connections() >= 1, 60,
             'the simulator connected to /cmd_vel')
        now_steps, crossed, trace = 0, None, []
        closest = {'white': math.inf, 'yellow': math.inf}
        chunk = int(round(0.1 / self.dt_s))
        while now_steps * self.dt_s < self.sim_limit_s and crossed is None:
            self.step(chunk)
            now_steps += chunk
            x, y = self.pose()
            trace.append([round(now_steps * self.dt_s, 3), round(x, 4), round(y, 4)])
            for paint, d in self.clearance(x, y).items():
                closest[paint] = min(closest[paint], d)
            if closest['white'] == 0.0:
                crossed = [round(now_steps * self.dt_s, 3), round(x, 4), round(y, 4)]
        FIGURES.update({'mode': 'control', 'white_crossed_at': crossed,
                        'closest_m': {k: round(v, 4) for k, v in closest.items()},
                        'trace': trace[::10]})
        print('figures: %s' % {k: v for k, v in FIGURES.items() if k != 'trace'})
        self.assertIsNotNone(crossed, 'driving straight on never reached the white line')
        # at the first corner: straight on along y = -1.747 into the outer white line
        self.assertAlmostEqual(crossed[2], SPAWN[1], delta=0.02)
        self.assertTrue(1.6 < crossed[1] < 1.9, crossed)


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--mode', choices=('lane', 'control'), default='lane')
    parser.add_argument('--figures', default='')
    parser.add_argument('--logs', default='', help='folder for the launch files\' output')
    parser.add_argument('--sim-limit', type=float, default=90.0)
    parser.add_argument('--min-clearance', type=float, default=0.04)
    OPTIONS = parser.parse_args()
    unittest.main(argv=sys.argv[:1])
