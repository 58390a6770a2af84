"""Which joints get sliders, their ranges and zeros, and the positions of
every movable joint, mimic followers included (no ROS, no Qt)."""
import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional

from joint_sliders.urdf_joints import Mimic


class ModelError(ValueError):
    """The joints and the options do not fit together; the message says how."""


@dataclass
class ModelOptions:
    """The parameters of joint_state_publisher that shape the model."""
    use_mimic_tags: bool = True
    use_smallest_joint_limits: bool = True
    zeros: Dict[str, float] = field(default_factory=dict)
    dependent_joints: Dict[str, Mimic] = field(default_factory=dict)


@dataclass
class FreeJoint:
    """A joint the user moves with a slider."""
    name: str
    type: str
    lower: float
    upper: float
    zero: float
    position: float = 0.0
    velocity: Optional[float] = None
    effort: Optional[float] = None

    @property
    def unit(self):
        """Unit of the position: m for prismatic joints, rad otherwise."""
        return 'm' if self.type == 'prismatic' else 'rad'


def wrap_angle(angle_rad):
    """Maps an angle onto [-pi, pi]."""
    wrapped = math.fmod(angle_rad + math.pi, 2.0 * math.pi)
    if wrapped < 0.0:
        wrapped += 2.0 * math.pi
    return wrapped - math.pi


def _range_of(spec, use_smallest):
    lower, upper = spec.lower, spec.upper
    if use_smallest and spec.type != 'continuous':
        if spec.soft_lower is not None:
            lower = max(lower, spec.soft_lower)
        if spec.soft_upper is not None:
            upper = min(upper, spec.soft_upper)
        if lower > upper:
            raise ModelError(f'joint "{spec.name}": soft limits [{lower}, {upper}] leave no range')
    return lower, upper


def _zero_of(name, lower, upper, zeros):
    if name in zeros:
        zero = zeros[name]
        if not lower <= zero <= upper:
            raise ModelError(f'zeros/{name} = {zero} is outside the joint range '
                             f'[{lower:g}, {upper:g}]')
        return zero
    return 0.0 if lower <= 0.0 <= upper else (lower + upper) / 2.0


class JointModel:
    """The positions of a robot's movable joints.

    Free joints get sliders; followers (mimic tags, dependent_joints) are
    computed from their leader; fixed, floating and planar joints are left out.
    """

    def __init__(self, specs, options=None):
        options = options or ModelOptions()
        movable = [s for s in specs if s.movable]
        self.followers = self._followers(movable, options)
        self.order = [s.name for s in movable]
        self.free: Dict[str, FreeJoint] = {}
        for spec in movable:
            if spec.name in self.followers:
                continue
            lower, upper = _range_of(spec, options.use_smallest_joint_limits)
            zero = _zero_of(spec.name, lower, upper, options.zeros)
            self.free[spec.name] = FreeJoint(spec.name, spec.type, lower, upper, zero, zero)
        for name in options.zeros:
            if name not in self.free:
                raise ModelError(f'zeros/{name}: no free movable joint of that name')
        for name in self.followers:
            self._check_no_loop(name)

    @staticmethod
    def _followers(movable, options):
        names = {s.name for s in movable}
        followers = {}
        if options.use_mimic_tags:
            followers = {s.name: s.mimic for s in movable if s.mimic is not None}
        for name, mimic in options.dependent_joints.items():
            if name not in names:
                raise ModelError(f'dependent_joints/{name}: no movable joint of that name')
            followers[name] = mimic
        for name, mimic in followers.items():
            if mimic.leader not in names:
                raise ModelError(f'joint "{name}" follows "{mimic.leader}", '
                                 'which is not a movable joint of this robot')
        return followers

    def _check_no_loop(self, name):
        chain = [name]
        while chain[-1] in self.followers:
            leader = self.followers[chain[-1]].leader
            if leader in chain:
                raise ModelError('mimic joints form a loop: ' + ' -> '.join(chain + [leader]))
            chain.append(leader)

    @property
    def slider_joints(self) -> List[FreeJoint]:
        """The free joints in URDF order: one slider each."""
        return [self.free[name] for name in self.order if name in self.free]

    def set_position(self, name, position):
        """Sets a free joint within its range (continuous joints wrap); returns the value kept."""
        joint = self.free[name]
        if joint.type == 'continuous':
            position = wrap_angle(position)
        joint.position = min(max(position, joint.lower), joint.upper)
        return joint.position

    def center(self):
        """Every free joint to its zero (0, the middle of the range, or its `zeros` entry)."""
        for joint in self.free.values():
            joint.position = joint.zero

    def randomize(self, rng):
        """Every free joint to a uniform random position in its range (rng: random.Random)."""
        for joint in self.slider_joints:
            joint.position = rng.uniform(joint.lower, joint.upper)

    def apply_source(self, names, positions, velocities, efforts):
        """Takes the values of a JointState from a source_list topic; returns the names used."""
        used = []
        for i, name in enumerate(names):
            joint = self.free.get(name)
            if joint is None:
                continue
            if i < len(positions):
                joint.position = positions[i]
            if i < len(velocities):
                joint.velocity = velocities[i]
            if i < len(efforts):
                joint.effort = efforts[i]
            used.append(name)
        return used

    def position(self, name):
        """Position of any movable joint, followers computed through their leaders."""
        if name in self.free:
            return self.free[name].position
        mimic = self.followers[name]
        return mimic.multiplier * self.position(mimic.leader) + mimic.offset

    def _rate(self, name, attr):
        if name in self.free:
            return getattr(self.free[name], attr)
        mimic = self.followers[name]
        leader = self._rate(mimic.leader, attr)
        return None if leader is None else mimic.multiplier * leader

    def joint_state(self, default_velocities=False, default_efforts=False):
        """(names, positions, velocities, efforts) of every movable joint in URDF order.

        Velocities and efforts are filled when their default flag is set or a
        source supplied some (missing values are 0); otherwise they are empty."""
        velocities = [self._rate(n, 'velocity') for n in self.order]
        efforts = [self._rate(n, 'effort') for n in self.order]

        def filled(values, default):
            if default or any(v is not None for v in values):
                return [0.0 if v is None else v for v in values]
            return []
        positions = [self.position(n) for n in self.order]
        return (list(self.order), positions, filled(velocities, default_velocities),
                filled(efforts, default_efforts))
