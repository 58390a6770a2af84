"""The node's parameters, read once and checked (no ROS: a lookup function is passed in)."""
import math
from dataclasses import dataclass, field
from typing import List, Optional

from joint_sliders.joint_model import ModelOptions
from joint_sliders.urdf_joints import Mimic


class ConfigError(ValueError):
    """A parameter has a wrong type or value; the message names it."""


@dataclass
class Config:
    """Everything the node reads from the parameter server."""
    rate_hz: float = 10.0
    source_list: List[str] = field(default_factory=list)
    model: ModelOptions = field(default_factory=ModelOptions)
    publish_default_velocities: bool = False
    publish_default_efforts: bool = False
    random_seed: Optional[int] = None
    layout_report: str = ''


def _number(name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or \
            not math.isfinite(value):
        raise ConfigError(f'parameter {name} = {value!r} is not a finite number')
    return float(value)


def _flag(name, value):
    if not isinstance(value, bool):
        raise ConfigError(f'parameter {name} = {value!r} is not a boolean')
    return value


def _zeros(value):
    if not isinstance(value, dict):
        raise ConfigError(f'parameter zeros = {value!r} is not a dictionary joint: position')
    return {str(k): _number(f'zeros/{k}', v) for k, v in value.items()}


def _dependent(value):
    if not isinstance(value, dict):
        raise ConfigError(f'parameter dependent_joints = {value!r} is not a dictionary')
    result = {}
    for name, entry in value.items():
        where = f'dependent_joints/{name}'
        if not isinstance(entry, dict) or not isinstance(entry.get('parent'), str):
            raise ConfigError(f'parameter {where} = {entry!r} needs a "parent" joint name')
        unknown = set(entry) - {'parent', 'factor', 'offset'}
        if unknown:
            raise ConfigError(f'parameter {where} has unknown keys {sorted(unknown)}')
        result[str(name)] = Mimic(entry['parent'],
                                  _number(f'{where}/factor', entry.get('factor', 1.0)),
                                  _number(f'{where}/offset', entry.get('offset', 0.0)))
    return result


def read_config(get):
    """Builds the Config; get(name, default) looks a parameter up (private first, then global)."""
    rate_hz = _number('rate', get('rate', 10))
    if rate_hz <= 0.0:
        raise ConfigError(f'parameter rate = {rate_hz:g} must be above 0 Hz')
    sources = get('source_list', [])
    if not isinstance(sources, list) or not all(isinstance(s, str) and s for s in sources):
        raise ConfigError(f'parameter source_list = {sources!r} is not a list of topic names')
    seed = get('random_seed', None)
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, int)):
        raise ConfigError(f'parameter random_seed = {seed!r} is not an integer')
    report = get('layout_report', '')
    if not isinstance(report, str):
        raise ConfigError(f'parameter layout_report = {report!r} is not a file path')
    model = ModelOptions(_flag('use_mimic_tags', get('use_mimic_tags', True)),
                         _flag('use_smallest_joint_limits',
                               get('use_smallest_joint_limits', True)),
                         _zeros(get('zeros', {})), _dependent(get('dependent_joints', {})))
    return Config(rate_hz, list(sources), model,
                  _flag('publish_default_velocities', get('publish_default_velocities', False)),
                  _flag('publish_default_efforts', get('publish_default_efforts', False)),
                  seed, report)
