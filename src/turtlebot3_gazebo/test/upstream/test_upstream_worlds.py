#!/usr/bin/python3
"""The TurtleBot3 worlds of a user's clone of turtlebot3_simulations, run unchanged through
their own launch files, against what Gazebo Classic shows of the same files.

Set MOBILITY_UPSTREAM_WS to a built catkin workspace (on top of this one) that holds the
clone's turtlebot3_gazebo and turtlebot3_description; without it the tests are skipped and
say so. Nothing of the clone is part of this repository: the expected values are computed
here from the clone's own files (gazebo_truth.py), never from the simulator.
"""
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import unittest

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gazebo_truth  # noqa: E402

UPSTREAM = os.environ.get('MOBILITY_UPSTREAM_WS', '')
PORT = 11771


def upstream_package(name):
    path = os.path.join(UPSTREAM, 'src', name)
    if os.path.isdir(path):
        return path
    for root, dirs, _ in os.walk(os.path.join(UPSTREAM, 'src')):
        if name in dirs:
            return os.path.join(root, name)
    return ''


class Launched:
    """roslaunch of the clone's launch file on a master of its own; stopped on exit."""

    def __init__(self, launch, model='burger'):
        env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % PORT,
                   TURTLEBOT3_MODEL=model, PATH='/usr/bin:/bin:' + os.environ['PATH'])
        setup = os.path.join(UPSTREAM, 'devel', 'setup.bash')
        self.env = env
        self.setup = setup
        self.log = tempfile.TemporaryFile(mode='w+')
        self.process = subprocess.Popen(
            ['bash', '-c', 'source %s && exec roslaunch -p %d turtlebot3_gazebo %s'
             % (setup, PORT, launch)], env=env, stdout=self.log,
            stderr=subprocess.STDOUT, universal_newlines=True, start_new_session=True)

    def output(self):
        """What roslaunch and its nodes have printed so far."""
        self.log.flush()
        self.log.seek(0)
        return self.log.read()

    def run(self, script, timeout=60):
        """A Python snippet run against the launch's master; returns its stdout."""
        out = subprocess.run(['bash', '-c', 'source %s && /usr/bin/python3 -c "$0"' % self.setup,
                              script], env=self.env, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, universal_newlines=True, timeout=timeout)
        if out.returncode != 0 or not out.stdout.strip():
            raise RuntimeError('probe exited %d: %s' % (out.returncode, out.stderr[-2000:]))
        return out.stdout.strip().splitlines()[-1]

    def __enter__(self):
        return self

    def __exit__(self, *args):
        os.killpg(self.process.pid, signal.SIGINT)
        try:
            self.process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()


READ_SCAN_AND_POSE = r'''
import rospy, math, json
from sensor_msgs.msg import LaserScan
from gazebo_msgs.srv import GetModelState
rospy.init_node('truth_probe')
rospy.wait_for_service('/gazebo/get_model_state', timeout=60)
scan = rospy.wait_for_message('/scan', LaserScan, timeout=60)
state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)('%s', 'world')
p, q = state.pose.position, state.pose.orientation
print(json.dumps({'ranges': [r if math.isfinite(r) else None for r in scan.ranges],
                  'angle_min': scan.angle_min, 'angle_max': scan.angle_max,
                  'range_min': scan.range_min, 'range_max': scan.range_max,
                  'pose': [p.x, p.y, p.z, q.x, q.y, q.z, q.w]}))
'''

READ_IMAGE = r'''
import rospy, json, base64
from sensor_msgs.msg import Image
rospy.init_node('image_probe')
rospy.sleep(1.0)
image = rospy.wait_for_message('%s', Image, timeout=60)
print(json.dumps({'w': image.width, 'h': image.height, 'enc': image.encoding,
                  'data': base64.b64encode(bytes(image.data)).decode(),
                  'description': rospy.get_param('/robot_description')}))
'''


def pose_matrix(values):
    x, y, z, qx, qy, qz, qw = values
    T = np.eye(4)
    T[:3, :3] = np.array([
        [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
        [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
        [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])
    T[:3, 3] = [x, y, z]
    return T


def compare_with_ray_cast(test, data, world_path, model_roots):
    """The scan of `data` (READ_SCAN_AND_POSE) against the Burger's lidar rays cast in the
    world file's geometry; returns (finite rays simulated, finite rays cast)."""
    T = pose_matrix(data['pose'])
    yaw = math.atan2(T[1, 0], T[0, 0])
    # The Burger's base_scan: 0.010 + 0.172 above the footprint, 0.032 behind its centre.
    lidar = T[:3, 3] + T[:3, :3] @ np.array([-0.032, 0, 0.182])
    shapes = gazebo_truth.world_shapes(world_path, model_roots)
    truth = gazebo_truth.lidar_ranges(shapes, lidar[0], lidar[1], lidar[2], yaw,
                                      samples=len(data['ranges']),
                                      angle_min=data['angle_min'], angle_max=data['angle_max'],
                                      range_min=data['range_min'], range_max=data['range_max'])
    sim = [r if r is not None else math.inf for r in data['ranges']]
    finite_truth = sum(map(math.isfinite, truth))
    finite_sim = sum(map(math.isfinite, sim))
    # Readings near range_max flip between finite and inf with the 0.01 m noise.
    test.assertLessEqual(abs(finite_sim - finite_truth), 3, (finite_sim, finite_truth))
    errors = sorted(abs(a - b) for a, b in zip(sim, truth)
                    if math.isfinite(a) and math.isfinite(b))
    test.assertLess(errors[len(errors) // 2], 0.015)      # noise sd 0.01: median 0.0067
    test.assertLess(errors[int(0.95 * len(errors))], 0.04)
    print('finite rays %d (Gazebo %d); |error| median %.4f, 95th %.4f m'
          % (finite_sim, finite_truth, errors[len(errors) // 2], errors[int(0.95 * len(errors))]))
    return sim, truth


@unittest.skipUnless(UPSTREAM and upstream_package('turtlebot3_gazebo'),
                     'MOBILITY_UPSTREAM_WS is not set to a built workspace with the clone of '
                     'turtlebot3_simulations: the upstream worlds are not tried')
class UpstreamWorlds(unittest.TestCase):
    def test_turtlebot3_world_scan_is_the_ray_cast_of_its_files(self):
        gazebo = upstream_package('turtlebot3_gazebo')
        with Launched('turtlebot3_world.launch') as launched:
            data = json.loads(launched.run(READ_SCAN_AND_POSE % 'turtlebot3_burger'))
        sim, truth = compare_with_ray_cast(
            self, data, os.path.join(gazebo, 'worlds', 'turtlebot3_world.world'),
            [os.path.join(gazebo, 'models')])
        behind = len(sim) // 2
        self.assertAlmostEqual(sim[behind], truth[behind], delta=0.04)

    def test_stage_1_runs_its_xacro_command_and_sees_the_square(self):
        """The training fork's stage launches (of the Melodic era) call
        `$(find xacro)/xacro.py`, ROBOTIS's noetic ones `$(find xacro)/xacro`: either way the
        robot comes up where the launch puts it and its lidar sees the square's walls."""
        gazebo = upstream_package('turtlebot3_gazebo')
        with open(os.path.join(gazebo, 'launch', 'turtlebot3_stage_1.launch')) as f:
            deprecated_name = '$(find xacro)/xacro.py' in f.read()
        with Launched('turtlebot3_stage_1.launch') as launched:
            data = json.loads(launched.run(READ_SCAN_AND_POSE % 'turtlebot3_burger'))
            output = launched.output()
        self.assertNotIn('RLException', output)
        self.assertNotIn('no such command', output)
        self.assertEqual('xacro.py is deprecated; please use xacro instead' in output,
                         deprecated_name)
        self.assertAlmostEqual(data['pose'][0], 0.0, delta=0.01)   # the launch's x_pos, y_pos
        self.assertAlmostEqual(data['pose'][1], 0.0, delta=0.01)
        sim, _ = compare_with_ray_cast(
            self, data, os.path.join(gazebo, 'worlds', 'turtlebot3_stage_1.world'),
            [os.path.join(gazebo, 'models')])
        self.assertGreater(sum(map(math.isfinite, sim)), 300)  # walls all round within 3.5 m

    def test_autorace_camera_shows_the_course_lanes_where_the_texture_puts_them(self):
        import base64
        gazebo = upstream_package('turtlebot3_gazebo')
        with Launched('turtlebot3_autorace.launch') as launched:
            image = json.loads(launched.run(READ_IMAGE % '/camera/image'))
            state = json.loads(launched.run(READ_SCAN_AND_POSE % 'turtlebot3_burger'))
        sim = np.frombuffer(base64.b64decode(image['data']), np.uint8).reshape(
            image['h'], image['w'], 3)
        if image['enc'] == 'bgr8':
            sim = sim[:, :, ::-1]
        link, T_link_sensor, hfov, width, height = gazebo_truth.urdf_camera(image['description'])
        T_link = gazebo_truth.urdf_link_poses(image['description'])[link]
        T_world_camera = pose_matrix(state['pose']) @ T_link @ T_link_sensor
        course = os.path.join(gazebo, 'models', 'turtlebot3_autorace', 'course')
        texture = cv2.imread(os.path.join(course, 'materials', 'textures', 'course.png'))[:, :, ::-1]
        # The course: a 4 m plane at the world's <include> pose (0 0 0, yaw -1.54).
        T_course = gazebo_truth.pose_matrix('0 0 0 0 0 -1.54')
        truth, hit = gazebo_truth.textured_plane_view(T_world_camera, hfov, width, height,
                                                      T_course, (4.0, 4.0), texture)
        self.assertEqual((width, height), (image['w'], image['h']))
        # Compared where the course is in view (the sky is a light grey, as white as paint).
        sim_yellow, sim_white = (mask & hit for mask in gazebo_truth.paint_classes(sim))
        true_yellow, true_white = (mask & hit for mask in gazebo_truth.paint_classes(truth))
        for name, s, t in (('yellow', sim_yellow, true_yellow), ('white', sim_white, true_white)):
            overlap = (s & t).sum() / max(1, (s | t).sum())
            print('%s paint: %d pixels drawn, %d from the texture, overlap %.2f'
                  % (name, s.sum(), t.sum(), overlap))
            self.assertGreater(t.sum(), 200, name)
            self.assertGreater(overlap, 0.6, '%s: %d sim, %d true pixels' % (name, s.sum(), t.sum()))
        # The lane: yellow line left of the robot, white line right of it.
        columns = np.arange(width)[None, :].repeat(height, 0)
        self.assertLess(columns[sim_yellow].mean(), width / 2)
        self.assertGreater(columns[sim_white].mean(), width / 2)


if __name__ == '__main__':
    unittest.main()
