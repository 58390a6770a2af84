"""Parameters: defaults, joint_state_publisher's names, and errors that name the value."""
import unittest

from joint_sliders.config import ConfigError, read_config
from joint_sliders.urdf_joints import Mimic


def lookup(params):
    return lambda name, default: params.get(name, default)


class ConfigTest(unittest.TestCase):

    def test_defaults(self):
        config = read_config(lookup({}))
        self.assertEqual(config.rate_hz, 10.0)
        self.assertEqual(config.source_list, [])
        self.assertTrue(config.model.use_mimic_tags)
        self.assertTrue(config.model.use_smallest_joint_limits)
        self.assertIsNone(config.random_seed)

    def test_values(self):
        config = read_config(lookup({
            'rate': 25, 'source_list': ['/a/joint_states'], 'zeros': {'j': 0.5},
            'use_gui': True, 'dependent_joints': {'k': {'parent': 'j', 'factor': 2}},
            'random_seed': 3, 'publish_default_velocities': True}))
        self.assertEqual(config.rate_hz, 25.0)
        self.assertEqual(config.source_list, ['/a/joint_states'])
        self.assertEqual(config.model.zeros, {'j': 0.5})
        self.assertEqual(config.model.dependent_joints, {'k': Mimic('j', 2.0, 0.0)})
        self.assertEqual(config.random_seed, 3)
        self.assertTrue(config.publish_default_velocities)

    def assert_error(self, params, *fragments):
        with self.assertRaises(ConfigError) as ctx:
            read_config(lookup(params))
        for fragment in fragments:
            self.assertIn(fragment, str(ctx.exception))

    def test_bad_rate(self):
        self.assert_error({'rate': 0}, 'rate = 0', 'above 0')
        self.assert_error({'rate': 'fast'}, "rate = 'fast'")

    def test_bad_source_list(self):
        self.assert_error({'source_list': '/joint_states'}, 'source_list', 'list')

    def test_bad_zero(self):
        self.assert_error({'zeros': {'j': 'up'}}, "zeros/j = 'up'")

    def test_bad_flag(self):
        self.assert_error({'use_mimic_tags': 'yes'}, "use_mimic_tags = 'yes'")

    def test_bad_dependent_joint(self):
        self.assert_error({'dependent_joints': {'k': {'factor': 2}}}, 'dependent_joints/k',
                          'parent')
        self.assert_error({'dependent_joints': {'k': {'parent': 'j', 'gain': 2}}}, "['gain']")
