"""`rosrun gazebo_ros spawn_model`: Gazebo's command line for adding a model to the world.

    spawn_model -urdf|-sdf -param NAME|-file PATH|-stdin -model NAME
                [-x X -y Y -z Z -R ROLL -P PITCH -Y YAW] [-J JOINT VALUE ...]
                [-reference_frame FRAME] [-robot_namespace NS] [-gazebo_namespace NS]
                [-unpause] [-wait MODEL] [-package_to_model] [-b]

A wrong argument prints the usage and exits 1; a model that cannot be read or spawned
exits 1 with the reason; success exits 0.
"""
import argparse
import math
import os
import re
import sys
import xml.dom.minidom


class UsageError(Exception):
    pass


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError('%s\n%s: error: %s' % (self.format_usage().rstrip(), self.prog,
                                                 message))


def make_parser(default_namespace='/'):
    parser = _Parser(prog='spawn_model',
                     description='Spawns a model (URDF or SDF) in the simulation.')
    fmt = parser.add_mutually_exclusive_group(required=True)
    fmt.add_argument('-urdf', action='store_true', help='the model is URDF')
    fmt.add_argument('-sdf', action='store_true', help='the model is SDF')
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument('-file', metavar='FILE_NAME', help='read the model from a file')
    source.add_argument('-param', metavar='PARAM_NAME', help='read the model from a parameter')
    source.add_argument('-database', metavar='MODEL_NAME',
                        help="Gazebo's online model database (not reachable here)")
    source.add_argument('-stdin', action='store_true', help='read the model from stdin')
    parser.add_argument('-model', required=True, metavar='MODEL_NAME', help='name of the model')
    parser.add_argument('-reference_frame', default='',
                        help='frame of the initial pose: "" or world, a model or model::link')
    parser.add_argument('-gazebo_namespace', default='/gazebo',
                        help='namespace of the simulator services (default /gazebo)')
    parser.add_argument('-robot_namespace', default=default_namespace,
                        help="namespace of the model's topics (default: this node's)")
    parser.add_argument('-unpause', action='store_true', help='unpause physics after spawning')
    parser.add_argument('-wait', metavar='MODEL_NAME',
                        help='wait until MODEL_NAME exists before spawning')
    for axis, help_text in (('x', 'x of the initial position, m'),
                            ('y', 'y of the initial position, m'),
                            ('z', 'z of the initial position, m'),
                            ('R', 'roll of the initial orientation, rad'),
                            ('P', 'pitch of the initial orientation, rad'),
                            ('Y', 'yaw of the initial orientation, rad')):
        parser.add_argument('-' + axis, type=float, default=0.0, help=help_text)
    parser.add_argument('-J', dest='joints', default=[], action='append', nargs=2,
                        metavar=('JOINT_NAME', 'JOINT_POSITION'),
                        help='initial joint position (repeatable)')
    parser.add_argument('-package_to_model', action='store_true',
                        help='turn package:// URIs into model:// ones')
    parser.add_argument('-b', dest='bond', action='store_true',
                        help='delete the model when this node is stopped')
    return parser


def parse_args(argv, default_namespace='/'):
    """Parses spawn_model's arguments (ROS remappings removed). Raises UsageError."""
    args = make_parser(default_namespace).parse_args([a for a in argv if ':=' not in a])
    for name in 'xyzRPY':
        value = getattr(args, name)
        if not math.isfinite(value):
            raise UsageError('spawn_model: error: -%s %s is not a finite number' % (name, value))
    joints = []
    for joint, value in args.joints:
        try:
            position = float(value)
        except ValueError:
            raise UsageError('spawn_model: error: -J %s %s: the position is not a number'
                             % (joint, value))
        if not math.isfinite(position):
            raise UsageError('spawn_model: error: -J %s %s is not finite' % (joint, value))
        joints.append((joint, position))
    args.joints = joints
    if args.database:
        raise UsageError("spawn_model: error: -database %s: Gazebo's online model database "
                         'cannot be reached here; use -file or -param' % args.database)
    return args


def quaternion_from_rpy(roll, pitch, yaw):
    """(x, y, z, w) of the fixed-axis rotation roll about x, then pitch about y, then yaw
    about z, as URDF and Gazebo define rpy."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def package_to_model(model_xml):
    """package://PKG/... -> model://PKG/..., for models whose packages are on the model path."""
    return re.sub(r'package://', 'model://', model_xml)


def check_xml(model_xml, source):
    """Raises ValueError naming the source when the text is empty or not XML."""
    if not model_xml.strip():
        raise ValueError('%s is empty' % source)
    try:
        xml.dom.minidom.parseString(model_xml)
    except Exception as error:  # expat raises its own ExpatError
        raise ValueError('%s is not valid XML: %s' % (source, error))


def read_file(path):
    if not os.path.exists(path):
        raise ValueError('specified file %s does not exist' % path)
    if not os.path.isfile(path):
        raise ValueError('specified file %s is not a file' % path)
    with open(path) as model_file:
        return model_file.read()
