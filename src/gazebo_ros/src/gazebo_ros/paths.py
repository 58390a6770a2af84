"""Gazebo's search paths as gazebo_ros users set them.

Gazebo finds `model://` folders in GAZEBO_MODEL_PATH, world names such as
`worlds/empty.world` in GAZEBO_RESOURCE_PATH, and gazebo_ros adds the paths that packages
export in their package.xml (`<export><gazebo_ros gazebo_model_path="..."/></export>`),
collected with `rospack plugins --attrib=ATTRIB gazebo_ros` (a package must depend on
gazebo_ros for rospack to list it).
"""
import os
import subprocess

# package.xml export attribute -> environment variable it extends
EXPORTS = (
    ('gazebo_model_path', 'GAZEBO_MODEL_PATH'),
    ('gazebo_media_path', 'GAZEBO_RESOURCE_PATH'),
    ('plugin_path', 'GAZEBO_PLUGIN_PATH'),
)


def _start(command):
    try:
        return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                universal_newlines=True)
    except OSError:
        return None


def _start_rospack(attrib, rospack):
    return _start(list(rospack) + ['plugins', '--attrib=' + attrib, 'gazebo_ros'])


def _paths_of(process):
    if process is None:
        return []
    out = process.communicate()[0]
    paths = []
    for line in out.splitlines():
        _, _, value = line.strip().partition(' ')
        for path in value.split(':'):
            path = path.strip()
            if path and path not in paths:
                paths.append(path)
    return paths


def exported_paths(attrib, rospack=('rospack',)):
    """The values of `<gazebo_ros ATTRIB="..."/>` of every package that depends on
    gazebo_ros, in rospack's order, `${prefix}` already expanded by rospack."""
    return _paths_of(_start_rospack(attrib, rospack))


def split(value):
    return [p for p in (value or '').split(':') if p]


def gazebo_environment(env, share_dir=None, rospack=('rospack',)):
    """A copy of `env` whose Gazebo paths also hold the package exports and this
    package's own folder (for `worlds/...` names; None: where `rospack find gazebo_ros`
    says). Entries already set come first, as in Gazebo."""
    env = dict(env)
    # Each rospack crawls the packages; they run side by side.
    running = [_start_rospack(attrib, rospack) for attrib, _ in EXPORTS]
    if share_dir is None:
        found = _start(list(rospack) + ['find', 'gazebo_ros'])
        share_dir = found.communicate()[0].strip() if found else ''
    for (_, variable), process in zip(EXPORTS, running):
        paths = split(env.get(variable))
        for path in _paths_of(process):
            if path not in paths:
                paths.append(path)
        if variable == 'GAZEBO_RESOURCE_PATH' and share_dir and share_dir not in paths:
            paths.append(share_dir)
        env[variable] = ':'.join(paths)
    return env


def workspace_executable(project, name, env):
    """`lib/PROJECT/NAME` in the first catkin workspace of CMAKE_PREFIX_PATH that has it,
    or None: what catkin's find_in_workspaces(['libexec'], ...) finds, without importing
    catkin_pkg (40 ms at every start of the simulator)."""
    for prefix in split(env.get('CMAKE_PREFIX_PATH')):
        if not os.path.isfile(os.path.join(prefix, '.catkin')):
            continue
        path = os.path.join(prefix, 'lib', project, name)
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return None


class WorldNotFound(Exception):
    pass


def server_environment(world, env, cwd=None, rospack=('rospack',)):
    """The environment gzserver starts the simulator in, and the world file it loads. A
    world given as a file needs no lookup, and the environment stays as it is: the
    simulator collects the packages' exported model folders itself while it loads the
    world. A world given by name is looked up in GAZEBO_RESOURCE_PATH with the exports
    added (`rospack plugins`, a crawl of the package path each)."""
    try:
        return dict(env), resolve_world(world, {}, cwd)  # a file: no folders to search
    except WorldNotFound:
        env = gazebo_environment(env, rospack=rospack)
        return env, resolve_world(world, env, cwd)


def resolve_world(name, env, cwd=None):
    """The file a world argument names: an existing path (absolute or relative to
    `cwd`), else a name looked up in every GAZEBO_RESOURCE_PATH folder, as gzserver does.
    Raises WorldNotFound naming the folders searched."""
    cwd = cwd or os.getcwd()
    candidate = name if os.path.isabs(name) else os.path.join(cwd, name)
    if os.path.isfile(candidate):
        return os.path.abspath(candidate)
    searched = split(env.get('GAZEBO_RESOURCE_PATH'))
    for folder in searched:
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            return os.path.abspath(path)
    raise WorldNotFound('world "%s" not found: not a file, and not in GAZEBO_RESOURCE_PATH (%s)'
                        % (name, ', '.join(searched) or 'empty'))
