"""Which joints get sliders, ranges, zeros, mimic followers, Center, Randomize, sources."""
import math
import os
import random
import unittest

from joint_sliders.joint_model import JointModel, ModelError, ModelOptions, wrap_angle
from joint_sliders.urdf_joints import Mimic, parse_joints

HERE = os.path.dirname(os.path.abspath(__file__))


def urdf_text(name):
    """Text of the fixture test/urdf/<name>."""
    with open(os.path.join(HERE, 'urdf', name), encoding='utf-8') as f:
        return f.read()


XQROBOT_URDF = os.path.join(HERE, '..', '..', '..', 'xqrobot_description', 'urdf',
                            'xqrobot_base.urdf')


def arm_model(**options):
    return JointModel(parse_joints(urdf_text('arm_minimal.urdf'))[1], ModelOptions(**options))


class SliderChoiceTest(unittest.TestCase):

    def test_one_slider_per_free_movable_joint(self):
        names = [j.name for j in arm_model().slider_joints]
        self.assertEqual(names, ['shoulder', 'lift', 'finger_left', 'wrist_roll'])

    def test_mimic_tags_can_be_ignored(self):
        names = [j.name for j in arm_model(use_mimic_tags=False).slider_joints]
        self.assertIn('finger_right', names)

    def test_ranges_use_soft_limits_unless_told_not_to(self):
        self.assertEqual(self._range(arm_model(), 'finger_left'), (0.005, 0.035))
        self.assertEqual(self._range(arm_model(use_smallest_joint_limits=False), 'finger_left'),
                         (0.0, 0.04))
        self.assertEqual(self._range(arm_model(), 'wrist_roll'), (-math.pi, math.pi))

    @staticmethod
    def _range(model, name):
        return model.free[name].lower, model.free[name].upper

    def test_fixed_only_robot_has_no_sliders_and_empty_state(self):
        model = JointModel(parse_joints(urdf_text('fixed_only.urdf'))[1])
        self.assertEqual(model.slider_joints, [])
        self.assertEqual(model.joint_state(), ([], [], [], []))

    def test_xqrobot_has_four_continuous_sliders(self):
        with open(XQROBOT_URDF, encoding='utf-8') as f:
            model = JointModel(parse_joints(f.read())[1])
        joints = model.slider_joints
        self.assertEqual(len(joints), 4)
        self.assertTrue({'left_wheel_joint', 'right_wheel_joint'} <= {j.name for j in joints})
        for joint in joints:
            self.assertEqual((joint.type, joint.lower, joint.upper),
                             ('continuous', -math.pi, math.pi))


class ZeroAndCenterTest(unittest.TestCase):

    def test_zero_is_0_or_middle_of_range(self):
        model = arm_model()
        zeros = {j.name: j.zero for j in model.slider_joints}
        self.assertEqual(zeros['shoulder'], 0.0)
        self.assertAlmostEqual(zeros['lift'], 0.2)
        self.assertAlmostEqual(zeros['finger_left'], 0.02)
        self.assertEqual(zeros['wrist_roll'], 0.0)
        self.assertEqual(model.position('lift'), zeros['lift'])

    def test_zeros_parameter_sets_start_and_center(self):
        model = arm_model(zeros={'shoulder': 1.0})
        self.assertEqual(model.position('shoulder'), 1.0)
        model.set_position('shoulder', -1.0)
        model.center()
        self.assertEqual(model.position('shoulder'), 1.0)

    def test_zeros_outside_range_names_joint(self):
        with self.assertRaisesRegex(ModelError, r'zeros/shoulder = 3\.0 .*\[-1\.5, 2\]'):
            arm_model(zeros={'shoulder': 3.0})

    def test_zeros_of_unknown_joint_names_it(self):
        with self.assertRaisesRegex(ModelError, 'zeros/elbow'):
            arm_model(zeros={'elbow': 0.0})

    def test_center_after_randomize(self):
        model = arm_model()
        model.randomize(random.Random(7))
        model.center()
        self.assertEqual({j.name: j.position for j in model.slider_joints},
                         {j.name: j.zero for j in model.slider_joints})


class PositionTest(unittest.TestCase):

    def test_set_position_clamps_to_range(self):
        model = arm_model()
        self.assertEqual(model.set_position('shoulder', 5.0), 2.0)
        self.assertEqual(model.set_position('lift', 0.0), 0.1)

    def test_continuous_wraps(self):
        model = arm_model()
        self.assertAlmostEqual(model.set_position('wrist_roll', 4.0), 4.0 - 2 * math.pi)
        self.assertAlmostEqual(wrap_angle(-4.0), 2 * math.pi - 4.0)

    def test_mimic_follows_leader(self):
        model = arm_model()
        model.set_position('finger_left', 0.03)
        self.assertAlmostEqual(model.position('finger_right'), -0.03 + 0.001)

    def test_dependent_joints_override(self):
        model = arm_model(dependent_joints={'lift': Mimic('shoulder', 0.1, 0.2)})
        self.assertNotIn('lift', model.free)
        model.set_position('shoulder', 1.0)
        self.assertAlmostEqual(model.position('lift'), 0.3)

    def test_randomize_is_seeded_and_in_range(self):
        first, second = arm_model(), arm_model()
        first.randomize(random.Random(42))
        second.randomize(random.Random(42))
        for joint in first.slider_joints:
            self.assertTrue(joint.lower <= joint.position <= joint.upper)
            self.assertEqual(joint.position, second.free[joint.name].position)
        self.assertNotEqual(first.position('shoulder'), 0.0)

    def test_joint_state_lists_every_movable_joint_in_order(self):
        model = arm_model()
        model.set_position('finger_left', 0.01)
        names, positions, velocities, efforts = model.joint_state()
        self.assertEqual(names, ['shoulder', 'lift', 'finger_left', 'finger_right',
                                 'wrist_roll'])
        self.assertAlmostEqual(positions[3], -0.009)
        self.assertEqual((velocities, efforts), ([], []))
        self.assertEqual(model.joint_state(True, True)[2:], ([0.0] * 5, [0.0] * 5))


class SourceTest(unittest.TestCase):

    def test_source_sets_known_free_joints_only(self):
        model = arm_model()
        used = model.apply_source(['wrist_roll', 'nonexistent', 'finger_right'],
                                  [1.25, 9.0, 0.5], [0.5, 1.0, 2.0], [])
        self.assertEqual(used, ['wrist_roll'])
        names, positions, velocities, efforts = model.joint_state()
        self.assertEqual(positions[names.index('wrist_roll')], 1.25)
        self.assertEqual(velocities[names.index('wrist_roll')], 0.5)
        self.assertEqual(velocities[names.index('shoulder')], 0.0)
        self.assertEqual(efforts, [])

    def test_source_with_names_only_keeps_positions(self):
        model = arm_model()
        model.set_position('shoulder', 0.5)
        model.apply_source(['shoulder'], [], [], [])
        self.assertEqual(model.position('shoulder'), 0.5)


class MimicErrorTest(unittest.TestCase):

    def test_loop_is_reported_with_its_joints(self):
        with self.assertRaisesRegex(ModelError, 'loop: a -> b -> a'):
            JointModel(parse_joints(urdf_text('invalid/mimic_loop.urdf'))[1])

    def test_unknown_leader_is_named(self):
        with self.assertRaisesRegex(ModelError, 'joint "a" follows "ghost"'):
            JointModel(parse_joints(urdf_text('invalid/mimic_unknown_leader.urdf'))[1])
