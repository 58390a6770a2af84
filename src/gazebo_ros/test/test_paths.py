#!/usr/bin/python3
"""Model and world paths collected as gazebo_ros collects them."""
import os
import shutil
import stat
import tempfile
import unittest

from gazebo_ros import paths, server


class TestPaths(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        # A stand-in for rospack that answers `rospack plugins --attrib=A gazebo_ros`.
        self.rospack = os.path.join(self.tmp, 'rospack')
        self.rospack_log = os.path.join(self.tmp, 'rospack.log')
        with open(self.rospack, 'w') as script:
            script.write('#!/bin/sh\necho "$@" >> %s\ncase "$2" in\n' % self.rospack_log +
                         '  --attrib=gazebo_model_path) echo "pkg_a /a/models:/a/more";'
                         ' echo "pkg_b /b/models";;\n'
                         '  --attrib=gazebo_media_path) echo "pkg_a /a/media";;\n'
                         '  gazebo_ros) echo "/share/found";;\n'
                         'esac\n')
        os.chmod(self.rospack, stat.S_IRWXU)

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_exports_follow_what_the_environment_already_holds(self):
        env = paths.gazebo_environment({'GAZEBO_MODEL_PATH': '/mine:/a/more'}, '/share/gz',
                                       rospack=(self.rospack,))
        self.assertEqual(env['GAZEBO_MODEL_PATH'], '/mine:/a/more:/a/models:/b/models')
        self.assertEqual(env['GAZEBO_RESOURCE_PATH'], '/a/media:/share/gz')
        self.assertEqual(env['GAZEBO_PLUGIN_PATH'], '')

    def test_the_package_folder_comes_from_rospack_find_when_not_given(self):
        env = paths.gazebo_environment({}, rospack=(self.rospack,))
        self.assertEqual(env['GAZEBO_RESOURCE_PATH'], '/a/media:/share/found')

    def test_the_node_is_found_in_the_first_catkin_workspace_that_has_it(self):
        def workspace(name, with_node):
            prefix = os.path.join(self.tmp, name)
            os.makedirs(os.path.join(prefix, 'lib', 'bullet_sim'))
            open(os.path.join(prefix, '.catkin'), 'w').close()
            if with_node:
                node = os.path.join(prefix, 'lib', 'bullet_sim', 'bullet_sim_node')
                open(node, 'w').close()
                os.chmod(node, stat.S_IRWXU)
            return prefix
        plain = os.path.join(self.tmp, 'plain')  # no .catkin: not a workspace
        os.makedirs(os.path.join(plain, 'lib', 'bullet_sim'))
        open(os.path.join(plain, 'lib', 'bullet_sim', 'bullet_sim_node'), 'w').close()
        env = {'CMAKE_PREFIX_PATH': ':'.join([plain, workspace('empty', False),
                                              workspace('devel', True), workspace('opt', True)])}
        self.assertEqual(paths.workspace_executable('bullet_sim', 'bullet_sim_node', env),
                         os.path.join(self.tmp, 'devel', 'lib', 'bullet_sim', 'bullet_sim_node'))
        self.assertIsNone(paths.workspace_executable('bullet_sim', 'nothing', env))
        self.assertIsNone(paths.workspace_executable('bullet_sim', 'bullet_sim_node', {}))

    def test_real_rospack_lists_exports_of_packages_depending_on_gazebo_ros(self):
        # Every path rospack reports must be a string without the package name in it.
        for path in paths.exported_paths('gazebo_model_path'):
            self.assertTrue(os.path.isabs(path), path)

    def test_world_names_resolve_like_gzserver(self):
        os.makedirs(os.path.join(self.tmp, 'res', 'worlds'))
        world = os.path.join(self.tmp, 'res', 'worlds', 'empty.world')
        open(world, 'w').close()
        env = {'GAZEBO_RESOURCE_PATH': '/nowhere:' + os.path.join(self.tmp, 'res')}
        self.assertEqual(paths.resolve_world('worlds/empty.world', env, cwd='/'), world)
        self.assertEqual(paths.resolve_world(world, {}, cwd='/'), world)
        self.assertEqual(paths.resolve_world('res/worlds/empty.world', {}, cwd=self.tmp), world)
        with self.assertRaisesRegex(paths.WorldNotFound,
                                    r'world "worlds/moon.world" not found: .*\(/nowhere, '):
            paths.resolve_world('worlds/moon.world', env, cwd='/')

    def rospack_calls(self):
        if not os.path.exists(self.rospack_log):
            return []
        with open(self.rospack_log) as log:
            return log.read().splitlines()

    def test_a_world_file_starts_the_simulator_without_crawling_the_packages(self):
        world = os.path.join(self.tmp, 'track.world')
        open(world, 'w').close()
        given = {'GAZEBO_MODEL_PATH': '/mine'}
        for name, cwd in ((world, '/'), ('track.world', self.tmp)):
            env, path = paths.server_environment(name, given, cwd=cwd, rospack=(self.rospack,))
            self.assertEqual((env, path), (given, world))
        self.assertEqual(self.rospack_calls(), [])

    def test_a_world_name_is_looked_up_with_the_exports(self):
        os.makedirs(os.path.join(self.tmp, 'media', 'worlds'))
        world = os.path.join(self.tmp, 'media', 'worlds', 'empty.world')
        open(world, 'w').close()
        env, path = paths.server_environment(
            'worlds/empty.world', {'GAZEBO_RESOURCE_PATH': os.path.join(self.tmp, 'media')},
            cwd='/', rospack=(self.rospack,))
        self.assertEqual(path, world)
        self.assertEqual(env['GAZEBO_MODEL_PATH'], '/a/models:/a/more:/b/models')
        self.assertIn('plugins --attrib=gazebo_media_path gazebo_ros', self.rospack_calls())


class TestServerArgs(unittest.TestCase):
    def test_empty_world_launch_arguments(self):
        # empty_world.launch paused:=true verbose:=true extra_gazebo_args:="--seed 7"
        args = server.parse(['-u', '', '--verbose', '-e', 'ode', '--seed', '7',
                             'worlds/empty.world', '__name:=gazebo', '__log:=/tmp/x.log'])
        self.assertTrue(args.paused)
        self.assertEqual(args.world, 'worlds/empty.world')
        self.assertEqual(args.seed, 7)
        self.assertEqual(args.ignored, ['--verbose'])
        self.assertEqual(server.node_arguments(args, '/w/empty.world'),
                         ['_world_file:=/w/empty.world', '_paused:=true', '_seed:=7',
                          '__name:=gazebo', '__log:=/tmp/x.log'])

    def test_recording_and_physics_are_accepted(self):
        args = server.parse(['-r', '-e', 'bullet', '--record_path', '/tmp/r', 'my.world'])
        self.assertFalse(args.paused)
        self.assertEqual(args.physics, 'bullet')
        self.assertEqual(args.ignored, ['-r', '--record_path /tmp/r'])

    def test_an_option_without_its_value_is_an_error(self):
        with self.assertRaisesRegex(ValueError, 'gzserver option -e needs a value'):
            server.parse(['-e'])


if __name__ == '__main__':
    unittest.main()
