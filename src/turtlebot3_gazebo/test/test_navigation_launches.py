#!/usr/bin/python3
"""roundTrack_navigation.launch and roundTrack_slam.launch without starting them.

Runnable without the navigation stack: with it absent (or hidden from rospack) each launch
stops at once with one message saying what to clone and build; with stand-in packages named
amcl, map_server, move_base and gmapping on ROS_PACKAGE_PATH, `roslaunch --nodes` and
`--dump-params` show the training's node names, frames Noetic accepts (no leading '/'),
Noetic's DWA parameter names, AMCL's first guess following the spawn pose, and no
world -> odom transform to fight the localiser's map -> odom.
"""
import os
import shutil
import subprocess
import tempfile
import unittest

import yaml

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAVIGATION_PACKAGES = ('amcl', 'map_server', 'move_base', 'gmapping')
KINETIC_DWA_NAMES = ('max_trans_vel', 'min_trans_vel', 'max_rot_vel', 'min_rot_vel')


def run(args, env, timeout=60):
    return subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout, env=env)


def without_navigation():
    """The environment less every ROS_PACKAGE_PATH entry that holds a navigation package."""
    env = dict(os.environ, PATH='/usr/bin:/bin:' + os.environ['PATH'])
    found = [run(['rospack', 'find', p], env).stdout.strip() for p in NAVIGATION_PACKAGES]
    entries = env.get('ROS_PACKAGE_PATH', '').split(':')
    keep = [e for e in entries if e and not any(
        f.startswith(e.rstrip('/') + '/') for f in found if f.startswith('/'))]
    env['ROS_PACKAGE_PATH'] = ':'.join(keep)
    return env


def with_stand_ins(folder):
    """without_navigation() plus empty packages of the navigation stack's names."""
    env = without_navigation()
    for name in NAVIGATION_PACKAGES:
        os.makedirs(os.path.join(folder, name))
        with open(os.path.join(folder, name, 'package.xml'), 'w') as f:
            f.write('<package format="2"><name>%s</name><version>0.0.0</version>'
                    '<description>stand-in</description><maintainer email="t@t.invalid">t'
                    '</maintainer><license>BSD</license></package>' % name)
    program = os.path.join(folder, 'map_server', 'map_server')  # for roslaunch --args
    with open(program, 'w') as f:
        f.write('#!/bin/sh\n')
    os.chmod(program, 0o755)
    env['ROS_PACKAGE_PATH'] = folder + ':' + env['ROS_PACKAGE_PATH']
    return env


class TestMissingNavigation(unittest.TestCase):
    def check(self, launch, message, missing):
        result = run(['roslaunch', 'turtlebot3_gazebo', launch, 'open_rviz:=false'],
                     without_navigation())
        self.assertNotEqual(result.returncode, 0, result.stdout)
        text = ' '.join(result.stdout.split())
        self.assertIn(message, text)
        self.assertIn('src/turtlebot3_gazebo/README.md, SLAM and navigation', text)
        self.assertIn('was not found in', text)
        self.assertIn(': %s ROS path' % missing, text)
        self.assertEqual(text.count('Resource not found'), 1)
        self.assertNotIn('process[', result.stdout)  # nothing started
        self.assertNotIn('started roslaunch server', result.stdout)

    def test_navigation_says_what_to_build(self):
        self.check('roundTrack_navigation.launch',
                   'The ROS navigation stack (amcl, map_server, move_base) is not built: '
                   'clone ros-planning/navigation (branch noetic-devel)', 'amcl')

    def test_slam_says_what_to_build(self):
        self.check('roundTrack_slam.launch',
                   'gmapping and map_server are not built: clone ros-perception/slam_gmapping '
                   'and ros-perception/openslam_gmapping (branch melodic-devel)', 'gmapping')


class TestLaunchContents(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix='nav_stand_ins_')
        cls.env = with_stand_ins(cls.tmp)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def nodes(self, launch, *args):
        result = run(['roslaunch', '--nodes', 'turtlebot3_gazebo', launch] + list(args),
                     self.env)
        self.assertEqual(result.returncode, 0, result.stdout)
        return set(result.stdout.split())

    def params(self, launch, *args):
        result = run(['roslaunch', '--dump-params', 'turtlebot3_gazebo', launch] + list(args),
                     self.env)
        self.assertEqual(result.returncode, 0, result.stdout)
        return yaml.safe_load(result.stdout)

    def spawn_args(self, *args):
        result = run(['roslaunch', '--args', '/spawn_urdf', 'turtlebot3_gazebo',
                      'roundTrack_navigation.launch'] + list(args), self.env)
        self.assertEqual(result.returncode, 0, result.stdout)
        return result.stdout

    def test_navigation_nodes_as_the_training_names_them(self):
        nodes = self.nodes('roundTrack_navigation.launch')
        self.assertLessEqual({'/gazebo', '/spawn_urdf', '/robot_state_publisher', '/map_server',
                              '/amcl', '/move_base', '/rviz', '/map_to_world'}, nodes)
        self.assertNotIn('/world_to_odom', nodes)
        self.assertNotIn('/rviz', self.nodes('roundTrack_navigation.launch', 'open_rviz:=false'))

    def test_slam_nodes_as_the_training_names_them(self):
        nodes = self.nodes('roundTrack_slam.launch')
        self.assertLessEqual({'/gazebo', '/turtlebot3_slam_gmapping', '/rviz', '/map_to_world'},
                             nodes)
        self.assertNotIn('/world_to_odom', nodes)
        params = self.params('roundTrack_slam.launch')
        gmapping = params['/turtlebot3_slam_gmapping/base_frame'], \
            params['/turtlebot3_slam_gmapping/odom_frame'], params['/turtlebot3_slam_gmapping/map_frame']
        self.assertEqual(gmapping, ('base_footprint', 'odom', 'map'))
        self.assertIs(params['/use_sim_time'], True)

    def test_the_simulation_keeps_its_world_to_odom_unless_told(self):
        self.assertIn('/world_to_odom', self.nodes('roundTrack_simulation.launch'))
        self.assertNotIn('/world_to_odom', self.nodes('roundTrack_simulation.launch',
                                                      'world_to_odom:=false'))

    def test_frames_carry_no_leading_slash(self):
        params = self.params('roundTrack_navigation.launch')
        self.assertEqual(params['/move_base/global_costmap/global_frame'], 'map')
        self.assertEqual(params['/move_base/local_costmap/global_frame'], 'odom')
        for costmap in ('global_costmap', 'local_costmap'):
            self.assertEqual(params['/move_base/%s/robot_base_frame' % costmap], 'base_footprint')
        frames = {k: v for k, v in params.items() if k.endswith(('frame', 'frame_id'))}
        self.assertGreaterEqual(len(frames), 7, frames)
        for key, value in frames.items():
            self.assertFalse(str(value).startswith('/'), '%s: %s' % (key, value))
        self.assertIs(params['/use_sim_time'], True)

    def test_costmap_layers_as_noetic_names_them(self):
        params = self.params('roundTrack_navigation.launch')
        layers = {c: [p['name'] for p in params['/move_base/%s/plugins' % c]]
                  for c in ('global_costmap', 'local_costmap')}
        self.assertEqual(layers, {
            'global_costmap': ['static_layer', 'obstacle_layer', 'inflation_layer'],
            'local_costmap': ['obstacle_layer', 'inflation_layer']})
        for costmap in layers:
            prefix = '/move_base/%s/' % costmap
            self.assertEqual(params[prefix + 'inflation_layer/inflation_radius'], 0.35)
            self.assertEqual(params[prefix + 'obstacle_layer/scan/sensor_frame'], 'base_scan')

    def test_dwa_parameters_have_noetic_names(self):
        params = self.params('roundTrack_navigation.launch')
        self.assertEqual(params['/move_base/base_local_planner'], 'dwa_local_planner/DWAPlannerROS')
        dwa = {k.split('/')[-1]: v for k, v in params.items()
               if k.startswith('/move_base/DWAPlannerROS/')}
        self.assertEqual((dwa['max_vel_trans'], dwa['min_vel_trans']), (0.22, 0.11))
        self.assertEqual((dwa['max_vel_theta'], dwa['min_vel_theta']), (2.75, 1.37))
        for name in KINETIC_DWA_NAMES:
            self.assertNotIn(name, dwa)
        self.assertEqual(dwa['min_vel_x'], -0.22)
        forward = self.params('roundTrack_navigation.launch', 'move_forward_only:=true')
        self.assertEqual(forward['/move_base/DWAPlannerROS/min_vel_x'], 0.0)

    def test_amcl_starts_at_the_spawn_pose(self):
        params = self.params('roundTrack_navigation.launch')
        guess = [params['/amcl/initial_pose_%s' % k] for k in 'xya']
        self.assertEqual(guess, [0.0, 0.0, 1.5675])
        self.assertIn('-x 0.0 -y 0.0 -z 0.0 -R 0 -P 0 -Y 1.5675', self.spawn_args())
        moved = self.params('roundTrack_navigation.launch', 'x_pos:=0.2', 'y_pos:=-1.0',
                            'yaw:=1.2')
        self.assertEqual([moved['/amcl/initial_pose_%s' % k] for k in 'xya'], [0.2, -1.0, 1.2])
        off = self.params('roundTrack_navigation.launch', 'initial_pose_x:=0.3')
        self.assertEqual(off['/amcl/initial_pose_x'], 0.3)
        self.assertIn('-x 0.0 -y 0.0', self.spawn_args('initial_pose_x:=0.3'))
        self.assertIn('-x 0.2 -y -1.0 -z 0.0 -R 0 -P 0 -Y 1.2',
                      self.spawn_args('x_pos:=0.2', 'y_pos:=-1.0', 'yaw:=1.2'))

    def test_map_server_serves_the_round_track(self):
        result = run(['roslaunch', '--args', '/map_server', 'turtlebot3_gazebo',
                      'roundTrack_navigation.launch'], self.env)
        self.assertIn(os.path.join(PACKAGE, 'maps', 'roundTrack.yaml'), result.stdout)

    def test_rviz_shows_map_costmaps_plans_and_particles(self):
        with open(os.path.join(PACKAGE, 'rviz', 'roundTrack_navigation.rviz')) as f:
            config = yaml.safe_load(f)
        manager = config['Visualization Manager']
        topics = {d.get('Topic') for d in manager['Displays']}
        self.assertLessEqual({'/map', '/move_base/global_costmap/costmap',
                              '/move_base/local_costmap/costmap', '/move_base/NavfnROS/plan',
                              '/move_base/DWAPlannerROS/local_plan', '/particlecloud', '/scan'},
                             topics)
        self.assertEqual(manager['Global Options']['Fixed Frame'], 'map')
        tools = {t['Class']: t.get('Topic') for t in manager['Tools']}
        self.assertEqual(tools['rviz/SetInitialPose'], '/initialpose')
        self.assertEqual(tools['rviz/SetGoal'], '/move_base_simple/goal')


if __name__ == '__main__':
    unittest.main()
