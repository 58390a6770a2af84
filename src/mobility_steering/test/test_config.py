import unittest

from mobility_steering.config import ConfigError, SteeringConfig, TeleopConfig


def params(**values):
    return lambda name, default: values.get(name, default)


class SteeringConfigTest(unittest.TestCase):
    def test_defaults_are_the_burger_limits(self):
        config = SteeringConfig.from_params(params())
        self.assertEqual(config.topic, '/cmd_vel')
        self.assertEqual((config.vx_min_mps, config.vx_max_mps), (-0.22, 0.22))
        self.assertEqual((config.vw_min_radps, config.vw_max_radps), (-2.84, 2.84))
        self.assertEqual(config.rate_hz, 10.0)

    def test_parameters_override(self):
        config = SteeringConfig.from_params(params(default_topic='/robot/cmd_vel',
                                                   default_vx_max=0.5))
        self.assertEqual((config.topic, config.vx_max_mps), ('/robot/cmd_vel', 0.5))

    def test_inverted_limits_name_both_parameters(self):
        with self.assertRaisesRegex(ConfigError, r'~default_vx_min \(0.3\).*~default_vx_max'):
            SteeringConfig.from_params(params(default_vx_min=0.3))

    def test_non_number_is_named(self):
        with self.assertRaisesRegex(ConfigError, "~default_vw_max must be a number, got 'x'"):
            SteeringConfig.from_params(params(default_vw_max='x'))

    def test_bad_topic_is_named(self):
        with self.assertRaisesRegex(ConfigError, '~default_topic'):
            SteeringConfig.from_params(params(default_topic='  '))

    def test_zero_rate_is_rejected(self):
        with self.assertRaisesRegex(ConfigError, '~rate must be positive, got 0.0'):
            SteeringConfig.from_params(params(rate=0))


class TeleopConfigTest(unittest.TestCase):
    def test_defaults(self):
        config = TeleopConfig.from_params(params())
        self.assertEqual((config.speed_limit_mps, config.turn_limit_radps), (0.22, 2.84))
        self.assertEqual(config.repeat_rate_hz, 0.0)

    def test_negative_repeat_rate_is_named(self):
        with self.assertRaisesRegex(ConfigError, '~repeat_rate .* got -1.0'):
            TeleopConfig.from_params(params(repeat_rate=-1))
