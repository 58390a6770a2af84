#!/usr/bin/python3
"""What Gazebo Classic shows of a world, computed from its files alone.

This module shares no code with the simulator: it reads SDF with ElementTree and COLLADA
with its own reader (Gazebo Classic's rules: <unit> applied, <up_axis> ignored, issue 1305),
and casts rays analytically (boxes, cylinders, spheres) or against triangles (meshes). Tests
compare the simulator's scans with these rays.
"""
import math
import os
import xml.etree.ElementTree as ET

import numpy as np

COLLADA_NS = '{http://www.collada.org/2005/11/COLLADASchema}'


def rpy_matrix(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch),
                              math.sin(pitch), math.cos(yaw), math.sin(yaw))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def pose_matrix(text):
    """4x4 of an SDF <pose> text 'x y z roll pitch yaw'."""
    values = [float(v) for v in (text or '').split()] + [0.0] * 6
    T = np.eye(4)
    T[:3, :3] = rpy_matrix(*values[3:6])
    T[:3, 3] = values[:3]
    return T


def child_pose(element):
    pose = element.find('pose')
    return pose_matrix(pose.text if pose is not None else '')


# ---------------------------------------------------------------------------------------
# COLLADA, as Gazebo Classic's loader reads it


def _floats(text):
    return np.array([float(v) for v in text.split()]) if text else np.zeros(0)


def _node_matrix(node):
    T = np.eye(4)
    for item in node:
        tag = item.tag.replace(COLLADA_NS, '')
        values = _floats(item.text)
        M = np.eye(4)
        if tag == 'matrix':
            M = values.reshape(4, 4)
        elif tag == 'translate':
            M[:3, 3] = values
        elif tag == 'scale':
            M = np.diag(list(values) + [1.0])
        elif tag == 'rotate':
            axis = values[:3] / np.linalg.norm(values[:3])
            angle = math.radians(values[3])
            K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]],
                          [-axis[1], axis[0], 0]])
            M[:3, :3] = np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
        else:
            continue
        T = T @ M
    return T


def _geometry_triangles(geometry):
    """Triangles (n, 3, 3) of a <geometry>'s <triangles> and <polylist> (all triangles)."""
    mesh = geometry.find(COLLADA_NS + 'mesh')
    sources = {}
    for source in mesh.findall(COLLADA_NS + 'source'):
        array = source.find(COLLADA_NS + 'float_array')
        accessor = source.find('.//' + COLLADA_NS + 'accessor')
        stride = int(accessor.get('stride', '1')) if accessor is not None else 3
        sources[source.get('id')] = _floats(array.text).reshape(-1, stride)
    vertices = mesh.find(COLLADA_NS + 'vertices')
    position_of_vertices = {}
    if vertices is not None:
        for inp in vertices.findall(COLLADA_NS + 'input'):
            if inp.get('semantic') == 'POSITION':
                position_of_vertices[vertices.get('id')] = inp.get('source').lstrip('#')
    out = []
    for prim in list(mesh.findall(COLLADA_NS + 'triangles')) + \
            list(mesh.findall(COLLADA_NS + 'polylist')):
        inputs = prim.findall(COLLADA_NS + 'input')
        stride = max(int(i.get('offset', '0')) for i in inputs) + 1
        offset, positions = None, None
        for inp in inputs:
            source = inp.get('source').lstrip('#')
            if inp.get('semantic') == 'VERTEX':
                offset, positions = int(inp.get('offset', '0')), sources[position_of_vertices[source]]
        p = prim.find(COLLADA_NS + 'p')
        if p is None or offset is None:
            continue
        indices = np.array([int(v) for v in p.text.split()]).reshape(-1, stride)[:, offset]
        counts = [3] * (len(indices) // 3)
        vcount = prim.find(COLLADA_NS + 'vcount')
        if vcount is not None:
            counts = [int(v) for v in vcount.text.split()]
        start = 0
        for n in counts:
            polygon = positions[indices[start:start + n], :3]
            for k in range(1, n - 1):  # a fan, as every loader triangulates convex polygons
                out.append([polygon[0], polygon[k], polygon[k + 1]])
            start += n
    return np.array(out).reshape(-1, 3, 3)


def collada_triangles(path):
    """Triangles of a COLLADA file in metres, in the file's own axes (up_axis ignored)."""
    root = ET.parse(path).getroot()
    unit = root.find(COLLADA_NS + 'asset/' + COLLADA_NS + 'unit')
    metres = float(unit.get('meter')) if unit is not None else 1.0
    geometries = {g.get('id'): g for g in root.iter(COLLADA_NS + 'geometry')}
    scene = root.find(COLLADA_NS + 'scene/' + COLLADA_NS + 'instance_visual_scene')
    scene_id = scene.get('url').lstrip('#') if scene is not None else None
    visual_scene = next((s for s in root.iter(COLLADA_NS + 'visual_scene')
                         if scene_id is None or s.get('id') == scene_id), None)
    out = []

    def visit(node, T_parent):
        T = T_parent @ _node_matrix(node)
        for instance in node.findall(COLLADA_NS + 'instance_geometry'):
            tris = _geometry_triangles(geometries[instance.get('url').lstrip('#')])
            homogeneous = np.concatenate([tris, np.ones(tris.shape[:2] + (1,))], axis=2)
            out.append((homogeneous @ T.T)[:, :, :3])
        for child in node.findall(COLLADA_NS + 'node'):
            visit(child, T)

    for node in visual_scene.findall(COLLADA_NS + 'node'):
        visit(node, np.diag([metres, metres, metres, 1.0]))
    return np.concatenate(out) if out else np.zeros((0, 3, 3))


# ---------------------------------------------------------------------------------------
# SDF worlds: static collision geometry in world coordinates


class Shape:
    """One collision geometry: kind, size, 4x4 world pose, triangles for meshes."""

    def __init__(self, kind, T_world, size=None, triangles=None, name=''):
        self.kind, self.T_world, self.size, self.triangles, self.name = (
            kind, T_world, size, triangles, name)


def resolve_uri(uri, model_roots, base_dir):
    if uri.startswith('model://'):
        rest = uri[len('model://'):]
        for root in model_roots:
            if os.path.exists(os.path.join(root, rest)):
                return os.path.join(root, rest)
        raise FileNotFoundError('%s not in %s' % (uri, model_roots))
    if uri.startswith('file://'):
        return uri[len('file://'):]
    return uri if os.path.isabs(uri) else os.path.join(base_dir, uri)


def _model_sdf(model_dir):
    config = ET.parse(os.path.join(model_dir, 'model.config')).getroot()
    sdfs = config.findall('sdf')
    return os.path.join(model_dir, sdfs[-1].text.strip())


def _collisions(model, T_model, model_roots, base_dir, name):
    shapes = []
    for link in model.findall('link'):
        T_link = T_model @ child_pose(link)
        for collision in link.findall('collision'):
            T = T_link @ child_pose(collision)
            geometry = collision.find('geometry')
            for kind in ('box', 'cylinder', 'sphere', 'plane', 'mesh'):
                g = geometry.find(kind)
                if g is None:
                    continue
                label = '%s::%s::%s' % (name, link.get('name'), collision.get('name'))
                if kind == 'box':
                    shapes.append(Shape('box', T, _floats(g.find('size').text), name=label))
                elif kind == 'cylinder':
                    shapes.append(Shape('cylinder', T, (float(g.find('radius').text),
                                                        float(g.find('length').text)), name=label))
                elif kind == 'plane':
                    normal = _floats(g.find('normal').text) if g.find('normal') is not None \
                        else np.array([0.0, 0.0, 1.0])
                    if not np.allclose(normal, [0, 0, 1]):
                        raise ValueError('%s: only planes facing +z are handled' % label)
                    size = g.find('size')
                    shapes.append(Shape('plane', T, tuple(_floats(size.text)) if size is not None
                                        else (0.0, 0.0), name=label))
                elif kind == 'sphere':
                    shapes.append(Shape('sphere', T, float(g.find('radius').text), name=label))
                else:
                    path = resolve_uri(g.find('uri').text.strip(), model_roots, base_dir)
                    scale = _floats(g.find('scale').text) if g.find('scale') is not None \
                        else np.ones(3)
                    tris = collada_triangles(path) * scale
                    homogeneous = np.concatenate([tris, np.ones(tris.shape[:2] + (1,))], axis=2)
                    shapes.append(Shape('mesh', T, triangles=(homogeneous @ T.T)[:, :, :3],
                                        name=label))
    for nested in model.findall('model'):
        shapes += _collisions(nested, T_model @ child_pose(nested), model_roots, base_dir, name)
    return shapes


def world_shapes(world_path, model_roots):
    """Collision shapes of every model of an SDF world (includes resolved in model_roots)."""
    world = ET.parse(world_path).getroot().find('world')
    base_dir = os.path.dirname(world_path)
    shapes = []
    for model in world.findall('model'):
        shapes += _collisions(model, child_pose(model), model_roots, base_dir, model.get('name'))
    for include in world.findall('include'):
        uri = include.find('uri').text.strip()
        if uri == 'model://sun':  # Gazebo's stock light: no geometry
            continue
        if uri == 'model://ground_plane':  # Gazebo's stock 100 m x 100 m plane at z = 0
            shapes.append(Shape('plane', np.eye(4), (100.0, 100.0), name='ground_plane'))
            continue
        model_dir = resolve_uri(uri, model_roots, base_dir)
        model = ET.parse(_model_sdf(model_dir)).getroot().find('model')
        pose = include.find('pose')
        T = pose_matrix(pose.text) if pose is not None else child_pose(model)
        shapes += _collisions(model, T, model_roots, model_dir, model.get('name'))
    return shapes


# ---------------------------------------------------------------------------------------
# Rays


def _ray_triangles(origin, direction, tris):
    """Distances along the unit ray to each triangle (inf where missed), both sides."""
    if len(tris) == 0:
        return np.full(0, np.inf)
    a, b, c = tris[:, 0], tris[:, 1], tris[:, 2]
    e1, e2 = b - a, c - a
    p = np.cross(direction, e2)
    det = np.einsum('ij,ij->i', e1, p)
    ok = np.abs(det) > 1e-12
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = origin - a
    u = np.einsum('ij,ij->i', s, p) * inv
    q = np.cross(s, e1)
    v = (q @ direction) * inv
    t = np.einsum('ij,ij->i', e2, q) * inv
    hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
    return np.where(hit, t, np.inf)


def _ray_local(shape, origin, direction):
    R, p = shape.T_world[:3, :3], shape.T_world[:3, 3]
    return R.T @ (origin - p), R.T @ direction


def _ray_box(shape, origin, direction):
    o, d = _ray_local(shape, origin, direction)
    half = shape.size / 2
    with np.errstate(divide='ignore', invalid='ignore'):
        t1, t2 = (-half - o) / d, (half - o) / d
    t_near = np.nanmax(np.minimum(t1, t2))
    t_far = np.nanmin(np.maximum(t1, t2))
    if t_near > t_far or t_far <= 0:
        return np.inf
    return t_near if t_near > 0 else t_far


def _ray_cylinder(shape, origin, direction):
    o, d = _ray_local(shape, origin, direction)
    radius, length = shape.size
    best = np.inf
    a = d[0] ** 2 + d[1] ** 2
    if a > 1e-15:
        b = 2 * (o[0] * d[0] + o[1] * d[1])
        c = o[0] ** 2 + o[1] ** 2 - radius ** 2
        disc = b * b - 4 * a * c
        if disc >= 0:
            for t in ((-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)):
                if t > 0 and abs(o[2] + t * d[2]) <= length / 2:
                    best = min(best, t)
    if abs(d[2]) > 1e-15:
        for zc in (-length / 2, length / 2):
            t = (zc - o[2]) / d[2]
            x, y = o[0] + t * d[0], o[1] + t * d[1]
            if t > 0 and x * x + y * y <= radius ** 2:
                best = min(best, t)
    return best


def _ray_sphere(shape, origin, direction):
    o, d = _ray_local(shape, origin, direction)
    b = 2 * o.dot(d)
    c = o.dot(o) - shape.size ** 2
    disc = b * b - 4 * c
    if disc < 0:
        return np.inf
    for t in ((-b - math.sqrt(disc)) / 2, (-b + math.sqrt(disc)) / 2):
        if t > 0:
            return t
    return np.inf


def _ray_plane(shape, origin, direction):
    """A plane facing its +z, size x by y (0 0: infinite), seen from either side."""
    o, d = _ray_local(shape, origin, direction)
    if abs(d[2]) < 1e-15:
        return np.inf
    t = -o[2] / d[2]
    x, y = o[0] + t * d[0], o[1] + t * d[1]
    sx, sy = shape.size
    inside = (sx <= 0 or abs(x) <= sx / 2) and (sy <= 0 or abs(y) <= sy / 2)
    return t if t > 0 and inside else np.inf


def cast(shapes, origin, direction):
    """Nearest distance from origin along the unit direction to any shape (inf if none)."""
    best = np.inf
    for shape in shapes:
        if shape.kind == 'mesh':
            hits = _ray_triangles(origin, direction, shape.triangles)
            t = hits.min() if len(hits) else np.inf
        elif shape.kind == 'box':
            t = _ray_box(shape, origin, direction)
        elif shape.kind == 'cylinder':
            t = _ray_cylinder(shape, origin, direction)
        elif shape.kind == 'plane':
            t = _ray_plane(shape, origin, direction)
        else:
            t = _ray_sphere(shape, origin, direction)
        best = min(best, t)
    return best


def lidar_ranges(shapes, x, y, z, yaw, samples=360, angle_min=0.0,
                 angle_max=2 * math.pi, range_min=0.12, range_max=3.5):
    """A planar lidar's readings as Gazebo's ray sensor gives them without noise: rays start
    at range_min, readings beyond range_max are +inf."""
    origin = np.array([x, y, z])
    out = []
    step = (angle_max - angle_min) / (samples - 1) if samples > 1 else 0
    for i in range(samples):
        angle = yaw + angle_min + i * step
        direction = np.array([math.cos(angle), math.sin(angle), 0.0])
        start = origin + range_min * direction
        t = cast(shapes, start, direction) + range_min
        out.append(t if t <= range_max else math.inf)
    return out


# ---------------------------------------------------------------------------------------
# Robots: link poses from a URDF's joints, a camera sensor's parameters


def urdf_link_poses(urdf_xml):
    """4x4 pose of every link in the root link's frame (joint origins only, joints at 0)."""
    root = ET.fromstring(urdf_xml)
    parent_of = {}
    for joint in root.findall('joint'):
        origin = joint.find('origin')
        xyz = _floats(origin.get('xyz', '0 0 0')) if origin is not None else np.zeros(3)
        rpy = _floats(origin.get('rpy', '0 0 0')) if origin is not None else np.zeros(3)
        T = np.eye(4)
        T[:3, :3] = rpy_matrix(*rpy)
        T[:3, 3] = xyz
        parent_of[joint.find('child').get('link')] = (joint.find('parent').get('link'), T)
    poses = {}

    def pose(link):
        if link not in poses:
            if link not in parent_of:
                poses[link] = np.eye(4)
            else:
                parent, T = parent_of[link]
                poses[link] = pose(parent) @ T
        return poses[link]

    for link in root.findall('link'):
        pose(link.get('name'))
    return poses


def urdf_camera(urdf_xml):
    """(reference link, 4x4 sensor pose in the link, hfov, width, height) of the URDF's
    first <gazebo> camera sensor."""
    root = ET.fromstring(urdf_xml)
    for gazebo in root.findall('gazebo'):
        for sensor in gazebo.findall('sensor'):
            if sensor.get('type') != 'camera':
                continue
            camera = sensor.find('camera')
            return (gazebo.get('reference'), child_pose(sensor),
                    float(camera.find('horizontal_fov').text),
                    int(camera.find('image/width').text), int(camera.find('image/height').text))
    raise ValueError('the URDF has no <gazebo> camera sensor')


def textured_plane_view(T_world_camera, hfov, width, height, T_world_plane, size, texture_rgb):
    """The image a pinhole camera (Gazebo's: x forward, y left, z up; pixel centres at
    +0.5, principal point at the image centre) takes of a textured plane facing +z, mapped
    as Gazebo's unit_plane (u from -x to +x, v = 0 at +y); None where a ray misses it."""
    focal = (width / 2.0) / math.tan(hfov / 2.0)
    cols, rows = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    rays = np.stack([np.ones_like(cols), -(cols - width / 2.0) / focal,
                     -(rows - height / 2.0) / focal], axis=-1)
    R_plane_camera = T_world_plane[:3, :3].T @ T_world_camera[:3, :3]
    origin = T_world_plane[:3, :3].T @ (T_world_camera[:3, 3] - T_world_plane[:3, 3])
    directions = rays @ R_plane_camera.T
    with np.errstate(divide='ignore', invalid='ignore'):
        t = -origin[2] / directions[..., 2]
    points = origin + t[..., None] * directions
    u = 0.5 + points[..., 0] / size[0]
    v = 0.5 - points[..., 1] / size[1]
    hit = (t > 0) & (u >= 0) & (u < 1) & (v >= 0) & (v < 1)
    th, tw = texture_rgb.shape[:2]
    x = np.clip((np.where(hit, u, 0) * tw).astype(int), 0, tw - 1)
    y = np.clip((np.where(hit, v, 0) * th).astype(int), 0, th - 1)
    image = texture_rgb[y, x].astype(float)
    return image, hit


def paint_classes(rgb):
    """Per pixel 'yellow', 'white' or '' by chromaticity, so that lighting does not count:
    yellow has red and green well above blue, white all three close and bright."""
    rgb = rgb.astype(float)
    top = rgb.max(axis=-1)
    low = rgb.min(axis=-1)
    yellow = (top > 60) & (rgb[..., 2] < 0.45 * top) & (np.minimum(rgb[..., 0], rgb[..., 1]) > 0.6 * top)
    white = (top > 100) & (low > 0.75 * top)
    return yellow, white
