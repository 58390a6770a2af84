"""Reading the joints of a robot from its URDF text (xml.etree, no ROS).

Only what a joint-slider tool needs is read: name, type, limits (with the
safety controller's soft limits), mimic tags. Bad input raises UrdfError with
a message that names the element and the value."""
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import Optional

JOINT_TYPES = ('revolute', 'continuous', 'prismatic', 'fixed', 'floating', 'planar')
SLIDER_TYPES = ('revolute', 'continuous', 'prismatic')


class UrdfError(ValueError):
    """The robot description cannot be used; the message says where and why."""


@dataclass(frozen=True)
class Mimic:
    """This joint's position is multiplier * leader + offset."""
    leader: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class JointSpec:
    """One joint as declared in the URDF."""
    name: str
    type: str
    lower: float = 0.0
    upper: float = 0.0
    soft_lower: Optional[float] = None
    soft_upper: Optional[float] = None
    mimic: Optional[Mimic] = None

    @property
    def movable(self):
        """True for the joint types that carry a single position value."""
        return self.type in SLIDER_TYPES

    @property
    def unit(self):
        """Unit of the joint's position."""
        return 'm' if self.type == 'prismatic' else 'rad'


def _float_attr(element, attr, where, default=None):
    text = element.get(attr)
    if text is None:
        if default is None:
            raise UrdfError(f'{where}: <{element.tag}> has no "{attr}" attribute')
        return default
    try:
        value = float(text)
    except ValueError:
        raise UrdfError(f'{where}: <{element.tag} {attr}="{text}"> is not a number') from None
    if not math.isfinite(value):
        raise UrdfError(f'{where}: <{element.tag} {attr}="{text}"> is not finite')
    return value


def _read_limits(element, where, jtype):
    if jtype == 'continuous':
        return -math.pi, math.pi
    limit = element.find('limit')
    if limit is None:
        raise UrdfError(f'{where}: a {jtype} joint needs a <limit lower=".." upper=".."/>')
    lower = _float_attr(limit, 'lower', where, 0.0)
    upper = _float_attr(limit, 'upper', where, 0.0)
    if lower > upper:
        raise UrdfError(f'{where}: <limit lower="{limit.get("lower")}" '
                        f'upper="{limit.get("upper")}">: lower is above upper')
    return lower, upper


def _read_soft_limits(element, where):
    safety = element.find('safety_controller')
    if safety is None:
        return None, None
    soft_lower = (_float_attr(safety, 'soft_lower_limit', where)
                  if safety.get('soft_lower_limit') is not None else None)
    soft_upper = (_float_attr(safety, 'soft_upper_limit', where)
                  if safety.get('soft_upper_limit') is not None else None)
    return soft_lower, soft_upper


def _read_mimic(element, where):
    mimic = element.find('mimic')
    if mimic is None:
        return None
    leader = mimic.get('joint')
    if not leader:
        raise UrdfError(f'{where}: <mimic> has no "joint" attribute')
    return Mimic(leader, _float_attr(mimic, 'multiplier', where, 1.0),
                 _float_attr(mimic, 'offset', where, 0.0))


def _read_joint(element, index):
    name = element.get('name')
    if not name:
        raise UrdfError(f'joint number {index + 1}: <joint> has no "name" attribute')
    jtype = element.get('type')
    where = f'joint "{name}"'
    if jtype not in JOINT_TYPES:
        raise UrdfError(f'{where}: unknown type "{jtype}" (expected one of '
                        f'{", ".join(JOINT_TYPES)})')
    if jtype not in SLIDER_TYPES:
        return JointSpec(name, jtype)
    lower, upper = _read_limits(element, where, jtype)
    soft_lower, soft_upper = _read_soft_limits(element, where)
    return JointSpec(name, jtype, lower, upper, soft_lower, soft_upper,
                     _read_mimic(element, where))


def parse_joints(urdf_text):
    """Returns the robot's name and its joints (JointSpec) in document order."""
    if not urdf_text or not urdf_text.strip():
        raise UrdfError('robot_description is empty')
    try:
        root = ET.fromstring(urdf_text)
    except ET.ParseError as err:
        raise UrdfError(f'robot_description is not valid XML: {err}') from None
    if root.tag != 'robot':
        raise UrdfError(f'robot_description: root element is <{root.tag}>, expected <robot>')
    joints = [_read_joint(el, i) for i, el in enumerate(root.findall('joint'))]
    seen = set()
    for joint in joints:
        if joint.name in seen:
            raise UrdfError(f'joint "{joint.name}" is declared twice')
        seen.add(joint.name)
    return root.get('name', ''), joints
