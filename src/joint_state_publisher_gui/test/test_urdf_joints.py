"""Reading joints from URDF: types, limits, soft limits, mimic tags, and the errors."""
import math
import os
import unittest

from joint_sliders.urdf_joints import Mimic, UrdfError, parse_joints

HERE = os.path.dirname(os.path.abspath(__file__))


def urdf_text(name):
    """Text of the fixture test/urdf/<name>."""
    with open(os.path.join(HERE, 'urdf', name), encoding='utf-8') as f:
        return f.read()


class ParseArmTest(unittest.TestCase):

    def setUp(self):
        self.name, joints = parse_joints(urdf_text('arm_minimal.urdf'))
        self.joints = {j.name: j for j in joints}
        self.order = [j.name for j in joints]

    def test_robot_name_and_document_order(self):
        self.assertEqual(self.name, 'test_arm')
        self.assertEqual(self.order, ['shoulder', 'lift', 'finger_left', 'finger_right',
                                      'wrist_roll', 'tool_mount'])

    def test_revolute_limits_and_unit(self):
        shoulder = self.joints['shoulder']
        self.assertEqual((shoulder.type, shoulder.lower, shoulder.upper), ('revolute', -1.5, 2.0))
        self.assertEqual(shoulder.unit, 'rad')

    def test_prismatic_is_in_metres(self):
        self.assertEqual(self.joints['lift'].unit, 'm')
        self.assertEqual((self.joints['lift'].lower, self.joints['lift'].upper), (0.1, 0.3))

    def test_continuous_spans_minus_pi_to_pi(self):
        wrist = self.joints['wrist_roll']
        self.assertEqual((wrist.lower, wrist.upper), (-math.pi, math.pi))

    def test_soft_limits_and_mimic(self):
        self.assertEqual((self.joints['finger_left'].soft_lower,
                          self.joints['finger_left'].soft_upper), (0.005, 0.035))
        self.assertEqual(self.joints['finger_right'].mimic, Mimic('finger_left', -1.0, 0.001))

    def test_fixed_is_not_movable(self):
        self.assertFalse(self.joints['tool_mount'].movable)
        self.assertTrue(self.joints['wrist_roll'].movable)


class ParseErrorTest(unittest.TestCase):
    """One fixture per failure mode; the message names the element and the value."""

    def assert_error(self, fixture, *fragments):
        with self.assertRaises(UrdfError) as ctx:
            parse_joints(urdf_text('invalid/' + fixture))
        for fragment in fragments:
            self.assertIn(fragment, str(ctx.exception))

    def test_revolute_without_limit(self):
        self.assert_error('revolute_no_limit.urdf', 'joint "j"', 'revolute', '<limit')

    def test_reversed_limits(self):
        self.assert_error('limits_reversed.urdf', 'joint "j"', 'lower="0.5"', 'upper="0.1"')

    def test_limit_not_a_number(self):
        self.assert_error('limit_not_number.urdf', 'joint "j"', 'upper="abc"', 'not a number')

    def test_unknown_type(self):
        self.assert_error('unknown_type.urdf', 'joint "j"', '"hinge"')

    def test_duplicate_joint(self):
        self.assert_error('duplicate_joint.urdf', 'joint "j"', 'twice')

    def test_not_xml(self):
        self.assert_error('not_xml.urdf', 'not valid XML')

    def test_empty_description(self):
        with self.assertRaisesRegex(UrdfError, 'empty'):
            parse_joints('  ')

    def test_wrong_root(self):
        with self.assertRaisesRegex(UrdfError, '<sdf>'):
            parse_joints('<sdf version="1.6"/>')
