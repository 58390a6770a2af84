"""MJCF text for the MuJoCo peer of the benchmark, built from the same URDF and SDF world
files that bullet_sim loads, so that dimensions, masses and walls cannot drift apart:

- every URDF link becomes a body at its joint's origin (fixed joints weld, continuous and
  revolute joints become hinges), with the URDF's inertial (no inertia from geoms), its
  box/cylinder/sphere collisions (geom group 1) and visuals (group 2, no contacts);
- robot parts collide with the world only (Gazebo's default: no self-collision), and the
  robot's friction (<mu1>/<mu2> of the Gazebo tags) wins over the ground's, as the smaller
  coefficient does in Gazebo;
- each wheel joint gets a velocity actuator limited to the plugin's torque;
- sites base_scan and imu_link carry the sensors, camera "head" looks along camera_link's +x
  with +z up at the URDF's horizontal field of view, rendered without multisampling (as
  Gazebo's cameras and bullet_sim's);
- the world's static boxes (walls: group 0, seen by the lidar) and the ground plane, with
  the world's ambient and directional light;
- with `textures` (the floor's and the walls' image files of textured_world.py), the ground
  wears the floor's image repeated every textured_world.FLOOR_TILE_M metres and the walls
  the walls' image, untinted, as the textured world's material scripts paint them.
"""
import math
import xml.etree.ElementTree as ET

import scenario
import textured_world

ROBOT_CONTACT = 'contype="2" conaffinity="1" priority="1"'
WORLD_CONTACT = 'contype="1" conaffinity="2"'
VISUAL_ONLY = 'contype="0" conaffinity="0" group="2" mass="0"'


def quat_from_rpy(roll, pitch, yaw):
    """URDF roll-pitch-yaw (fixed axes x, y, z) as a MuJoCo quaternion (w x y z)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy)


def fmt(values):
    return " ".join("%.9g" % v for v in values)


def origin_attrs(element):
    """pos and quat attributes of a URDF <origin> child (identity when absent)."""
    origin = element.find("origin") if element is not None else None
    xyz = [float(v) for v in origin.get("xyz", "0 0 0").split()] if origin is not None else [0] * 3
    rpy = [float(v) for v in origin.get("rpy", "0 0 0").split()] if origin is not None else [0] * 3
    return 'pos="%s" quat="%s"' % (fmt(xyz), fmt(quat_from_rpy(*rpy)))


def geom_shape(geometry):
    """type and size attributes of a URDF <geometry>, or None for meshes."""
    box, cylinder, sphere = geometry.find("box"), geometry.find("cylinder"), geometry.find("sphere")
    if box is not None:
        return 'type="box" size="%s"' % fmt(float(v) / 2 for v in box.get("size").split())
    if cylinder is not None:
        return 'type="cylinder" size="%s %s"' % (cylinder.get("radius"),
                                                  float(cylinder.get("length")) / 2)
    if sphere is not None:
        return 'type="sphere" size="%s"' % sphere.get("radius")
    return None


def link_friction(robot, link_name):
    """Mean of the link's Gazebo <mu1>/<mu2> (as bullet_sim takes it), default 1."""
    for gazebo in robot.findall("gazebo"):
        if gazebo.get("reference") == link_name and gazebo.find("mu1") is not None:
            return (float(gazebo.find("mu1").text) + float(gazebo.find("mu2").text)) / 2
    return 1.0


def link_body(robot, link, children, out, indent):
    """Geoms, inertial, sites and camera of one link, then its child links as bodies."""
    name = link.get("name")
    pad = " " * indent
    inertial = link.find("inertial")
    if inertial is not None:
        i = inertial.find("inertia")
        full = [float(i.get(k, "0")) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")]
        origin = inertial.find("origin")
        if origin is not None and any(float(v) for v in origin.get("rpy", "0 0 0").split()):
            raise scenario.SanityError("link %s: rotated inertial frames are not converted" % name)
        xyz = origin.get("xyz", "0 0 0") if origin is not None else "0 0 0"
        out.append('%s<inertial pos="%s" mass="%s" fullinertia="%s"/>' % (
            pad, xyz, inertial.find("mass").get("value"), fmt(full)))
    friction = link_friction(robot, name)
    for collision in link.findall("collision"):
        shape = geom_shape(collision.find("geometry"))
        if shape:
            out.append('%s<geom %s %s group="1" %s friction="%g 0.005 0.0001"/>' % (
                pad, shape, origin_attrs(collision), ROBOT_CONTACT, friction))
    for visual in link.findall("visual"):
        shape = geom_shape(visual.find("geometry"))
        if shape:
            out.append('%s<geom %s %s %s rgba="0.3 0.3 0.3 1"/>' % (
                pad, shape, origin_attrs(visual), VISUAL_ONLY))
    out.append('%s<site name="%s"/>' % (pad, name))
    if name == "camera_link":
        # MuJoCo cameras look along -z with +y up: x axis = link -y, y axis = link +z.
        vertical_fov = 2 * math.atan(math.tan(camera_hfov(robot) / 2) * 480 / 640)
        out.append('%s<camera name="head" xyaxes="0 -1 0 0 0 1" fovy="%g"/>' % (
            pad, math.degrees(vertical_fov)))
    for joint, child in children.get(name, []):
        out.append('%s<body name="%s" %s>' % (pad, child.get("name"), origin_attrs(joint)))
        if joint.get("type") in ("continuous", "revolute"):
            axis = joint.find("axis").get("xyz") if joint.find("axis") is not None else "1 0 0"
            out.append('%s  <joint name="%s" type="hinge" axis="%s"/>' % (
                pad, joint.get("name"), axis))
        link_body(robot, child, children, out, indent + 2)
        out.append('%s</body>' % pad)


def camera_hfov(robot):
    hfov = robot.find(".//sensor[@type='camera']/camera/horizontal_fov")
    return float(hfov.text) if hfov is not None else 1.5707


def robot_bodies(urdf_file):
    """The robot as a free body at the spawn pose, and the names of its wheel joints."""
    robot = ET.parse(urdf_file).getroot()
    links = {link.get("name"): link for link in robot.findall("link")}
    children, child_names = {}, set()
    for joint in robot.findall("joint"):
        parent, child = joint.find("parent").get("link"), joint.find("child").get("link")
        children.setdefault(parent, []).append((joint, links[child]))
        child_names.add(child)
    roots = [name for name in links if name not in child_names]
    if len(roots) != 1:
        raise scenario.SanityError("%s: %d root links" % (urdf_file, len(roots)))
    yaw = scenario.SPAWN_YAW_RAD
    out = ['<body name="%s" pos="0 0 0" quat="%s">' % (roots[0], fmt(quat_from_rpy(0, 0, yaw))),
           '  <freejoint name="root"/>']
    link_body(robot, links[roots[0]], children, out, 2)
    out.append("</body>")
    return "\n".join(out)


def world_geoms(world_file, textured=False):
    out = []
    for name, (x, y, z, yaw), size, rgba, collides in scenario.read_world(world_file):
        contact = 'group="0" ' + WORLD_CONTACT if collides else VISUAL_ONLY
        look = 'material="bench_wall"' if textured and name.startswith("wall_") \
            else 'rgba="%s"' % fmt(rgba)
        out.append('<geom name="%s" type="box" pos="%s" quat="%s" size="%s" %s %s/>' % (
            name, fmt((x, y, z)), fmt(quat_from_rpy(0, 0, yaw)), fmt(s / 2 for s in size),
            look, contact))
    return "\n".join(out)


def texture_assets(textures):
    """The <asset> of the floor's and the walls' images: the floor repeated every
    FLOOR_TILE_M metres (texuniform: repeats per metre), a wall's image once per face."""
    floor, wall = textures
    return """<asset>
    <texture name="bench_floor" type="2d" file="%s"/>
    <texture name="bench_wall" type="2d" file="%s"/>
    <material name="bench_floor" texture="bench_floor" texuniform="true" texrepeat="%g %g"/>
    <material name="bench_wall" texture="bench_wall"/>
  </asset>""" % (floor, wall, 1 / textured_world.FLOOR_TILE_M, 1 / textured_world.FLOOR_TILE_M)


def world_light(world_file):
    """The world's ambient and directional light, as MuJoCo's headlight ambient and a light."""
    root = ET.parse(world_file).getroot()
    ambient = root.find(".//scene/ambient")
    light = root.find(".//light[@type='directional']")
    ambient_rgb = ambient.text.split()[:3] if ambient is not None else ["0.4"] * 3
    headlight = '<headlight ambient="%s" diffuse="0 0 0" specular="0 0 0"/>' % " ".join(ambient_rgb)
    if light is None:
        return headlight, ""
    return headlight, '<light directional="true" castshadow="false" dir="%s" diffuse="%s" ' \
        'specular="0 0 0" pos="0 0 10"/>' % (light.find("direction").text,
                                            " ".join(light.find("diffuse").text.split()[:3]))


def build_mjcf(urdf_file, world_file, textures=None):
    headlight, light = world_light(world_file)
    torque = scenario.WHEEL_TORQUE_NM
    ground_look = 'material="bench_floor"' if textures else 'rgba="0.5 0.5 0.5 1"'
    return """<mujoco model="round_track_burger">
  <compiler angle="radian" inertiafromgeom="false" fusestatic="true"/>
  <option timestep="%g" integrator="implicitfast" gravity="0 0 -9.8"/>
  <visual>%s<quality offsamples="0"/><global offwidth="640" offheight="480"/></visual>
  %s
  <worldbody>
    %s
    <geom name="ground_plane" type="plane" size="50 50 0.1" %s group="0"
          %s friction="100 0.005 0.0001"/>
%s
%s
  </worldbody>
  <actuator>
    <velocity name="wheel_left_joint" joint="wheel_left_joint" kv="1" forcerange="-%g %g"/>
    <velocity name="wheel_right_joint" joint="wheel_right_joint" kv="1" forcerange="-%g %g"/>
  </actuator>
</mujoco>
""" % (scenario.STEP_S, headlight, texture_assets(textures) if textures else "", light,
       ground_look, WORLD_CONTACT, world_geoms(world_file, bool(textures)),
       robot_bodies(urdf_file), torque, torque, torque, torque)
