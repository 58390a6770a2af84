"""Expanding, checking and reading robot descriptions in tests, with the same
tools a user runs: xacro, check_urdf and urdf_to_graphiz."""
import os
import subprocess
import tempfile
import xml.etree.ElementTree as ET

import numpy as np


def xacro(path, *args):
    """Runs the workspace's xacro on a file and returns the URDF text."""
    result = subprocess.run(['rosrun', 'xacro', 'xacro', path, *args], capture_output=True,
                            text=True, timeout=60)
    if result.returncode != 0:
        raise RuntimeError(f'xacro {path} failed: {result.stderr.strip()}')
    return result.stdout


def check_urdf(urdf_text):
    """Runs check_urdf on URDF text; returns (exit code, combined output)."""
    with tempfile.NamedTemporaryFile('w', suffix='.urdf', delete=False) as f:
        f.write(urdf_text)
    try:
        result = subprocess.run(['check_urdf', f.name], capture_output=True, text=True,
                                timeout=60)
    finally:
        os.unlink(f.name)
    return result.returncode, result.stdout + result.stderr


def graphiz(urdf_text, workdir):
    """Runs urdf_to_graphiz in workdir; returns the text of the .gv file it wrote."""
    path = os.path.join(workdir, 'model.urdf')
    with open(path, 'w') as f:
        f.write(urdf_text)
    subprocess.run(['urdf_to_graphiz', path, os.path.join(workdir, 'graph')], check=True,
                   capture_output=True, timeout=60)
    with open(os.path.join(workdir, 'graph.gv')) as f:
        return f.read()


def joints(urdf_text):
    """{joint name: (type, parent, child)} of a URDF."""
    root = ET.fromstring(urdf_text)
    return {j.get('name'): (j.get('type'), j.find('parent').get('link'),
                            j.find('child').get('link'))
            for j in root.findall('joint')}


def links(urdf_text):
    """Set of link names of a URDF."""
    return {link.get('name') for link in ET.fromstring(urdf_text).findall('link')}


def roots(urdf_text):
    """Links that are no joint's child."""
    return links(urdf_text) - {child for _, _, child in joints(urdf_text).values()}


def rpy_matrix(roll, pitch, yaw):
    """Rotation matrix of URDF fixed-axis roll, pitch, yaw (Rz * Ry * Rx)."""
    cr, sr, cp, sp, cy, sy = (np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch),
                              np.cos(yaw), np.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def transform(xyz, rpy=(0.0, 0.0, 0.0)):
    """4x4 homogeneous transform of a URDF origin."""
    t = np.eye(4)
    t[:3, :3] = rpy_matrix(*rpy)
    t[:3, 3] = xyz
    return t


def chain(*origins):
    """Product of transforms given as (xyz, rpy) pairs, parent first."""
    result = np.eye(4)
    for xyz, rpy in origins:
        result = result @ transform(xyz, rpy)
    return result
