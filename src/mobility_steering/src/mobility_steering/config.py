"""Parameters of the steering window and the teleop, read once and validated.

Defaults are the TurtleBot3 Burger's limits: 0.22 m/s and 2.84 rad/s."""
from dataclasses import dataclass

BURGER_MAX_LINEAR_MPS = 0.22
BURGER_MAX_ANGULAR_RADPS = 2.84


class ConfigError(ValueError):
    """A parameter has a value the tools cannot work with; the message names it."""


def _number(get_param, name, default):
    value = get_param(name, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ConfigError(f'parameter ~{name} must be a number, got {value!r}')
    return float(value)


def _topic(get_param, name, default):
    value = get_param(name, default)
    if not isinstance(value, str) or not value.strip() or ' ' in value.strip():
        raise ConfigError(f'parameter ~{name} must be a topic name, got {value!r}')
    return value.strip()


def _positive(name, value):
    if value <= 0:
        raise ConfigError(f'parameter ~{name} must be positive, got {value}')


def _ordered(min_name, min_value, max_name, max_value):
    if not min_value < max_value:
        raise ConfigError(f'parameter ~{min_name} ({min_value}) must be below '
                          f'~{max_name} ({max_value})')


@dataclass(frozen=True)
class SteeringConfig:
    topic: str
    vx_min_mps: float
    vx_max_mps: float
    vw_min_radps: float
    vw_max_radps: float
    vx_step_mps: float
    vw_step_radps: float
    rate_hz: float
    zero_repeats: int

    @classmethod
    def from_params(cls, get_param):
        """Builds the config from get_param(name, default) (e.g. rospy.get_param on '~name')."""
        config = cls(
            topic=_topic(get_param, 'default_topic', '/cmd_vel'),
            vx_min_mps=_number(get_param, 'default_vx_min', -BURGER_MAX_LINEAR_MPS),
            vx_max_mps=_number(get_param, 'default_vx_max', BURGER_MAX_LINEAR_MPS),
            vw_min_radps=_number(get_param, 'default_vw_min', -BURGER_MAX_ANGULAR_RADPS),
            vw_max_radps=_number(get_param, 'default_vw_max', BURGER_MAX_ANGULAR_RADPS),
            vx_step_mps=_number(get_param, 'vx_step', 0.02),
            vw_step_radps=_number(get_param, 'vw_step', 0.2),
            rate_hz=_number(get_param, 'rate', 10.0),
            zero_repeats=int(_number(get_param, 'zero_repeats', 3)),
        )
        _ordered('default_vx_min', config.vx_min_mps, 'default_vx_max', config.vx_max_mps)
        _ordered('default_vw_min', config.vw_min_radps, 'default_vw_max', config.vw_max_radps)
        for name, value in (('vx_step', config.vx_step_mps), ('vw_step', config.vw_step_radps),
                            ('rate', config.rate_hz), ('zero_repeats', config.zero_repeats)):
            _positive(name, value)
        return config


@dataclass(frozen=True)
class TeleopConfig:
    topic: str
    speed_mps: float
    turn_radps: float
    speed_limit_mps: float
    turn_limit_radps: float
    repeat_rate_hz: float

    @classmethod
    def from_params(cls, get_param):
        config = cls(
            topic=_topic(get_param, 'topic', '/cmd_vel'),
            speed_mps=_number(get_param, 'speed', 0.1),
            turn_radps=_number(get_param, 'turn', 1.0),
            speed_limit_mps=_number(get_param, 'speed_limit', BURGER_MAX_LINEAR_MPS),
            turn_limit_radps=_number(get_param, 'turn_limit', BURGER_MAX_ANGULAR_RADPS),
            repeat_rate_hz=_number(get_param, 'repeat_rate', 0.0),
        )
        for name, value in (('speed', config.speed_mps), ('turn', config.turn_radps),
                            ('speed_limit', config.speed_limit_mps),
                            ('turn_limit', config.turn_limit_radps)):
            _positive(name, value)
        if config.repeat_rate_hz < 0:
            raise ConfigError(f'parameter ~repeat_rate must be 0 (off) or positive, '
                              f'got {config.repeat_rate_hz}')
        return config
