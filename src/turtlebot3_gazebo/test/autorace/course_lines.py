#!/usr/bin/python3
"""Where the lane lines of a textured course lie in the world, from its files alone.

Gazebo draws a model's `<plane>` visual with OGRE's unit plane: texture coordinate u runs
from the plane's -x edge (0) to its +x edge (1), v from its +y edge (0) to its -y edge (1),
and the whole image is stretched over the plane's `<size>` whatever its aspect. This module
reads the world's `<include>` of the course, the model's SDF (link and visual poses, the
plane's size), its OGRE material script (the `texture` of the named material) and the
image, classes each texel as white or yellow paint by its colour, and gives the distance
from a world point to the nearest painted texel (the texel as the square it covers).
No simulator is involved.
"""
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import cv2
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'upstream'))
import gazebo_truth  # noqa: E402


class CourseError(Exception):
    """A course that cannot be read: names the file and the element."""


def _text(element, path, where):
    found = element.find(path)
    if found is None or not (found.text or '').strip():
        raise CourseError('%s: no <%s>' % (where, path))
    return found.text.strip()


def _block(text, start):
    """The text of a brace block from just after its '{' to its matching '}'."""
    depth = 1
    for i in range(start, len(text)):
        depth += {'{': 1, '}': -1}.get(text[i], 0)
        if depth == 0:
            return text[start:i]
    return text[start:]


def material_texture(script_dirs, material_name, where):
    """The texture file of an OGRE material: the first `texture` of the material's
    `texture_unit`, looked up in the script folders' *.material files, the image in the
    same folders (Gazebo adds every <uri> of the <script> to OGRE's resource paths)."""
    texture = None
    for folder in script_dirs:
        if not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            if not name.endswith('.material'):
                continue
            text = open(os.path.join(folder, name)).read()
            match = re.search(r'material\s+%s\s*\{' % re.escape(material_name), text)
            if match:
                found = re.search(r'\btexture\s+(\S+)', _block(text, match.end()))
                if found:
                    texture = found.group(1)
    if texture is None:
        raise CourseError('%s: material %s with a texture not found in %s'
                          % (where, material_name, script_dirs))
    for folder in script_dirs:
        if os.path.exists(os.path.join(folder, texture)):
            return os.path.join(folder, texture)
    raise CourseError('%s: texture %s of material %s not found in %s'
                      % (where, texture, material_name, script_dirs))


class CourseLines:
    """The painted texels of the textured plane of the model included as `model_uri`."""

    def __init__(self, world_path, model_roots, model_uri):
        world = ET.parse(world_path).getroot().find('world')
        include = next((i for i in world.findall('include')
                        if (i.findtext('uri') or '').strip() == model_uri), None)
        if include is None:
            raise CourseError('%s: no <include> of %s' % (world_path, model_uri))
        model_dir = gazebo_truth.resolve_uri(model_uri, model_roots, os.path.dirname(world_path))
        sdf_path = os.path.join(model_dir, 'model.sdf')
        model = ET.parse(sdf_path).getroot().find('model')
        T_model = gazebo_truth.pose_matrix(_text(include, 'pose', world_path + ' <include>'))
        visual, T_link = None, None
        for link in model.findall('link'):
            for candidate in link.findall('visual'):
                if candidate.find('geometry/plane') is not None:
                    visual, T_link = candidate, gazebo_truth.child_pose(link)
        if visual is None:
            raise CourseError('%s: no <visual> with a <plane>' % sdf_path)
        where = '%s: <visual name="%s">' % (sdf_path, visual.get('name'))
        normal = [float(v) for v in _text(visual, 'geometry/plane/normal', where).split()]
        if not np.allclose(normal, [0, 0, 1]):
            raise CourseError('%s: <normal> %s: only planes facing +z are read' % (where, normal))
        self.size = tuple(float(v) for v in _text(visual, 'geometry/plane/size', where).split())
        if len(self.size) != 2 or min(self.size) <= 0:
            raise CourseError('%s: <size> %s is not two positive lengths' % (where, self.size))
        # the plane's frame in the world
        self.T_world_plane = T_model @ T_link @ gazebo_truth.child_pose(visual)
        script = visual.find('material/script')
        if script is None:
            raise CourseError('%s: no <material><script>' % where)
        dirs = [gazebo_truth.resolve_uri(u.text.strip(), model_roots, model_dir)
                for u in script.findall('uri')]
        self.texture_path = material_texture(dirs, _text(script, 'name', where), where)
        bgr = cv2.imread(self.texture_path, cv2.IMREAD_COLOR)
        if bgr is None:
            raise CourseError('%s: not an image' % self.texture_path)
        self.rows, self.cols = bgr.shape[:2]
        self.texel = (self.size[0] / self.cols, self.size[1] / self.rows)  # m along x, y
        yellow, white = gazebo_truth.paint_classes(bgr[:, :, ::-1])
        self.paint = {'white': self._texel_centres(white), 'yellow': self._texel_centres(yellow)}

    def _texel_centres(self, mask):
        """Plane coordinates (m) of the centres of the texels of a mask."""
        rows, cols = np.nonzero(mask)
        u = (cols + 0.5) / self.cols
        v = (rows + 0.5) / self.rows
        return np.stack([(u - 0.5) * self.size[0], (0.5 - v) * self.size[1]], axis=1)

    def plane_point(self, x, y):
        """A world point (on the ground) in the plane's coordinates."""
        p = np.linalg.inv(self.T_world_plane) @ np.array([x, y, 0.0, 1.0])
        return p[:2]

    def world_point(self, px, py):
        return (self.T_world_plane @ np.array([px, py, 0.0, 1.0]))[:2]

    def texel_at(self, x, y):
        """(row, column) of the texture at a world point, as Gazebo maps it."""
        px, py = self.plane_point(x, y)
        return (int(math.floor((0.5 - py / self.size[1]) * self.rows)),
                int(math.floor((px / self.size[0] + 0.5) * self.cols)))

    def distance(self, paint, x, y):
        """Distance (m) from a world point to the nearest texel of a paint ('white' or
        'yellow'), each texel the square it covers; 0 on a painted texel."""
        centres = self.paint[paint]
        if len(centres) == 0:
            return math.inf
        p = self.plane_point(x, y)
        d = np.maximum(np.abs(centres - p) - np.array(self.texel) / 2.0, 0.0)
        return float(np.sqrt((d ** 2).sum(axis=1)).min())
