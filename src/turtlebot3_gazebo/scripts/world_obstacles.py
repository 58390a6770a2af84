"""The obstacles of an SDF world seen from above: what a ground-truth map is drawn from.

Reads the world file with an XML parser and returns, for every collision shape of every
static model (a nested model of a static one is static too) that cuts the robot's height band, its footprint on the ground: a rotated
rectangle for a box, a circle for a cylinder or a sphere. Planes (the ground) have no
footprint. Poses of nested models, links and collisions are composed; they must be upright
(roll and pitch 0), as walls and posts are. Anything else the map cannot show faithfully
(a model:// include, a mesh) is an error naming the file, the element and the value.
"""
import collections
import math
import xml.etree.ElementTree as ET

Rectangle = collections.namedtuple('Rectangle', 'name x y yaw size_x size_y')
Circle = collections.namedtuple('Circle', 'name x y radius')

# The Burger stands 0.19 m tall; its lidar plane is 0.18 m up.
BAND_BOTTOM_M = 0.02
BAND_TOP_M = 0.30


class WorldError(Exception):
    """A world file the map cannot be drawn from."""


class _Pose2D(collections.namedtuple('_Pose2D', 'x y z yaw')):
    def then(self, child):
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return _Pose2D(self.x + c * child.x - s * child.y, self.y + s * child.x + c * child.y,
                       self.z + child.z, self.yaw + child.yaw)


def _numbers(text, count, where):
    try:
        values = [float(v) for v in (text or '').split()]
    except ValueError:
        values = []
    if len(values) != count:
        raise WorldError("%s: '%s' is not %d numbers" % (where, (text or '').strip(), count))
    return values


def _pose(element, where):
    node = element.find('pose')
    if node is None:
        return _Pose2D(0.0, 0.0, 0.0, 0.0)
    x, y, z, roll, pitch, yaw = _numbers(node.text, 6, where + ' <pose>')
    if abs(roll) > 1e-6 or abs(pitch) > 1e-6:
        raise WorldError('%s <pose>: roll %g, pitch %g: only upright shapes can be mapped'
                         % (where, roll, pitch))
    return _Pose2D(x, y, z, yaw)


def _in_band(z_centre, height):
    return z_centre + height / 2 > BAND_BOTTOM_M and z_centre - height / 2 < BAND_TOP_M


def _footprint(geometry, pose, name, where):
    shape = geometry[0] if len(geometry) else None
    kind = shape.tag if shape is not None else '(none)'
    if kind == 'plane':
        return None
    if kind == 'box':
        sx, sy, sz = _numbers(shape.findtext('size'), 3, where + ' <box><size>')
        return Rectangle(name, pose.x, pose.y, pose.yaw, sx, sy) if _in_band(pose.z, sz) else None
    if kind == 'cylinder':
        radius = _numbers(shape.findtext('radius'), 1, where + ' <cylinder><radius>')[0]
        length = _numbers(shape.findtext('length'), 1, where + ' <cylinder><length>')[0]
        return Circle(name, pose.x, pose.y, radius) if _in_band(pose.z, length) else None
    if kind == 'sphere':
        radius = _numbers(shape.findtext('radius'), 1, where + ' <sphere><radius>')[0]
        return Circle(name, pose.x, pose.y, radius) if _in_band(pose.z, 2 * radius) else None
    raise WorldError('%s <geometry>: <%s> cannot be mapped (box, cylinder, sphere, plane)'
                     % (where, kind))


def _model_footprints(model, parent_pose, parent_static, where):
    name = model.get('name', '?')
    where = "%s model '%s'" % (where, name)
    pose = parent_pose.then(_pose(model, where))
    static = parent_static or model.findtext('static', 'false').strip() in ('true', '1')
    if not static:
        return []
    footprints = []
    for link in model.findall('link'):
        link_where = "%s link '%s'" % (where, link.get('name', '?'))
        link_pose = pose.then(_pose(link, link_where))
        for collision in link.findall('collision'):
            c_where = "%s collision '%s'" % (link_where, collision.get('name', '?'))
            geometry = collision.find('geometry')
            if geometry is None:
                raise WorldError('%s: no <geometry>' % c_where)
            shape_name = '%s::%s' % (name, link.get('name', '?'))
            footprint = _footprint(geometry, link_pose.then(_pose(collision, c_where)),
                                   shape_name, c_where)
            if footprint is not None:
                footprints.append(footprint)
    for nested in model.findall('model'):
        footprints.extend(_model_footprints(nested, pose, static, where))
    return footprints


def read_footprints(world_path):
    """Footprints of the static collision shapes of the world in world_path."""
    try:
        root = ET.parse(world_path).getroot()
    except (OSError, ET.ParseError) as error:
        raise WorldError('%s: %s' % (world_path, error))
    world = root.find('world')
    if world is None:
        raise WorldError('%s: no <world> in <%s>' % (world_path, root.tag))
    where = "%s world '%s'" % (world_path, world.get('name', '?'))
    include = world.find('include')
    if include is not None:
        raise WorldError("%s <include> '%s': includes are not expanded; list the models"
                         % (where, include.findtext('uri', '').strip()))
    footprints = []
    for model in world.findall('model'):
        footprints.extend(_model_footprints(model, _Pose2D(0.0, 0.0, 0.0, 0.0), False, where))
    return footprints
