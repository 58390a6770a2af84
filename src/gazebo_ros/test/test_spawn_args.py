#!/usr/bin/python3
"""spawn_model's command line, as Gazebo users type it."""
import math
import unittest

from gazebo_ros import spawn


class TestSpawnArgs(unittest.TestCase):
    def test_the_trainings_command_line(self):
        args = spawn.parse_args(['-urdf', '-model', 'turtlebot3_burger', '-x', '0.0', '-y',
                                 '0.0', '-z', '0.0', '-R', '0', '-P', '0', '-Y', '1.5675',
                                 '-param', 'robot_description'])
        self.assertTrue(args.urdf)
        self.assertEqual(args.param, 'robot_description')
        self.assertEqual(args.model, 'turtlebot3_burger')
        self.assertEqual((args.x, args.y, args.z, args.R, args.P, args.Y),
                         (0.0, 0.0, 0.0, 0.0, 0.0, 1.5675))
        self.assertEqual(args.gazebo_namespace, '/gazebo')
        self.assertEqual(args.reference_frame, '')

    def test_joints_namespace_and_flags(self):
        args = spawn.parse_args(['-sdf', '-file', 'm.sdf', '-model', 'arm', '-J', 'shoulder',
                                 '0.5', '-J', 'elbow', '-1.25', '-unpause', '-wait', 'table',
                                 '-robot_namespace', 'tb3_1', '-reference_frame', 'table',
                                 '-gazebo_namespace', '/sim', '__name:=spawner'], '/ns/')
        self.assertEqual(args.joints, [('shoulder', 0.5), ('elbow', -1.25)])
        self.assertTrue(args.unpause)
        self.assertEqual((args.wait, args.robot_namespace, args.reference_frame,
                          args.gazebo_namespace), ('table', 'tb3_1', 'table', '/sim'))

    def test_robot_namespace_defaults_to_the_nodes(self):
        args = spawn.parse_args(['-urdf', '-param', 'd', '-model', 'm'], '/tb3_0/')
        self.assertEqual(args.robot_namespace, '/tb3_0/')

    def assertUsageError(self, argv, *fragments):
        with self.assertRaises(spawn.UsageError) as caught:
            spawn.parse_args(argv)
        message = str(caught.exception)
        self.assertIn('usage: spawn_model', message)
        for fragment in fragments:
            self.assertIn(fragment, message)

    def test_wrong_arguments_give_the_usage(self):
        self.assertUsageError(['-param', 'robot_description', '-model', 'm'],
                              'one of the arguments -urdf -sdf is required')
        self.assertUsageError(['-urdf', '-sdf', '-param', 'p', '-model', 'm'], 'not allowed')
        self.assertUsageError(['-urdf', '-param', 'p'], '-model')
        self.assertUsageError(['-urdf', '-param', 'p', '-model', 'm', '-x', 'left'],
                              "-x: invalid float value: 'left'")
        self.assertUsageError(['-urdf', '-param', 'p', '-model', 'm', '-speed', '3'],
                              'unrecognized arguments: -speed 3')

    def test_non_finite_values_are_refused(self):
        with self.assertRaisesRegex(spawn.UsageError, '-y nan is not a finite number'):
            spawn.parse_args(['-urdf', '-param', 'p', '-model', 'm', '-y', 'nan'])
        with self.assertRaisesRegex(spawn.UsageError, '-J wheel x: the position is not'):
            spawn.parse_args(['-urdf', '-param', 'p', '-model', 'm', '-J', 'wheel', 'x'])

    def test_the_model_database_is_out_of_reach(self):
        with self.assertRaisesRegex(spawn.UsageError, 'online model database'):
            spawn.parse_args(['-sdf', '-database', 'coke_can', '-model', 'can'])

    def test_quaternion_from_rpy(self):
        # yaw only: rotation of psi about z -> (0, 0, sin(psi/2), cos(psi/2))
        x, y, z, w = spawn.quaternion_from_rpy(0, 0, 1.5675)
        self.assertAlmostEqual(z, math.sin(1.5675 / 2))
        self.assertAlmostEqual(w, math.cos(1.5675 / 2))
        self.assertAlmostEqual(x, 0)
        self.assertAlmostEqual(y, 0)
        # roll of pi/2 then yaw of pi/2 (fixed axes): the body x axis ends on world y and
        # the body y axis on world z; check through the rotation matrix of the quaternion.
        x, y, z, w = spawn.quaternion_from_rpy(math.pi / 2, 0, math.pi / 2)
        body_x = (1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y))
        body_y = (2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x))
        for got, want in zip(body_x + body_y, (0, 1, 0, 0, 0, 1)):
            self.assertAlmostEqual(got, want)

    def test_model_text_checks(self):
        with self.assertRaisesRegex(ValueError, 'parameter robot_description is empty'):
            spawn.check_xml('  ', 'parameter robot_description')
        with self.assertRaisesRegex(ValueError, 'file a.urdf is not valid XML'):
            spawn.check_xml('<robot name="r">', 'file a.urdf')
        with self.assertRaisesRegex(ValueError, 'specified file /nonexistent.urdf does not'):
            spawn.read_file('/nonexistent.urdf')
        self.assertEqual(spawn.package_to_model('<mesh filename="package://p/m.stl"/>'),
                         '<mesh filename="model://p/m.stl"/>')


if __name__ == '__main__':
    unittest.main()
