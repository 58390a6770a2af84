"""bullet_sim's layers and the one direction of their includes.

A file's layer is named by its folder (src/core/<layer>/, include/bullet_sim/<layer>/,
src/node/, src/python/); an include's layer by the path it names. A layer may include itself
and the layers listed for it below, nothing else: description never includes physics,
nothing below the simulation includes it, and the node and the Python module see the core
only through its public headers (include/bullet_sim/).
"""
import os
import re

#: Each layer and the layers it may include (besides itself), lowest first.
ALLOWED = {
    'common': set(),
    'description': {'common'},
    'world': {'common'},
    'physics': {'common', 'description', 'world'},
    'sensors': {'common', 'description', 'world', 'physics'},
    'simulation': {'common', 'description', 'world', 'physics', 'sensors'},
    'render': {'common', 'description', 'world', 'physics', 'sensors', 'simulation'},
    'node': {'common', 'description', 'world', 'sensors', 'simulation', 'render'},
    'python': {'common', 'description', 'world', 'sensors', 'simulation', 'render'},
}
FOLDER_LAYERS = ('description', 'world', 'physics', 'sensors', 'render')
NODE_FOLDERS = ('services', 'topics', 'runner')
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


def layer_of_path(relpath):
    """The layer of a file given relative to the package, or None (tests, benches)."""
    parts = relpath.split('/')
    if parts[:2] == ['src', 'node']:
        return 'node'
    if parts[:2] == ['src', 'python']:
        return 'python'
    if parts[:2] == ['src', 'core']:
        rest = parts[2:]
    elif parts[:2] == ['include', 'bullet_sim']:
        rest = parts[2:]
    else:
        return None
    return layer_of_rest(rest)


def layer_of_rest(rest):
    """The layer of a path below src/core or include/bullet_sim."""
    if len(rest) > 1 and rest[0] in FOLDER_LAYERS:
        return rest[0]
    if len(rest) == 1 and rest[0].startswith('simulation'):
        return 'simulation'
    if len(rest) == 1 and rest[0] in ('types.h', 'errors.h'):
        return 'common'
    return None


def layer_of_include(name, including_layer):
    """The layer an #include names: 'private' for a core header outside include/bullet_sim
    seen from the node, None for a header that is not bullet_sim's."""
    parts = name.split('/')
    if parts[0] == 'bullet_sim':
        return layer_of_rest(parts[1:])
    private = parts[0] in FOLDER_LAYERS + ('src', '..') or name.startswith('simulation_impl')
    if including_layer in ('node', 'python'):
        if private:
            return 'private'
        own_node_header = including_layer == 'node' and len(parts) == 1
        return 'node' if parts[0] in NODE_FOLDERS or own_node_header else None
    return layer_of_rest(parts) or ('private' if private else None)


def violations(relpath, lines):
    """(line number, include, message) for each include of the file that breaks the rules."""
    layer = layer_of_path(relpath)
    if layer is None:
        return []
    found = []
    for number, line in enumerate(lines, 1):
        match = INCLUDE.match(line)
        if not match:
            continue
        name = match.group(1)
        target = layer_of_include(name, layer)
        if target is None or target == layer or target in ALLOWED[layer]:
            continue
        if target == 'private':
            why = 'the %s uses the core through include/bullet_sim/ only' % layer
        else:
            why = '%s may include %s' % (layer, ', '.join(sorted(ALLOWED[layer] | {layer})))
        found.append((number, name, '%s:%d: %s includes %s (%s): %s' % (
            relpath, number, layer, name, target, why)))
    return found


def check_package(package_dir):
    """Every violation in the package's sources, as messages."""
    messages = []
    for top in ('include', 'src'):
        for folder, _, files in os.walk(os.path.join(package_dir, top)):
            for name in sorted(files):
                if not name.endswith(('.h', '.cpp')):
                    continue
                path = os.path.join(folder, name)
                with open(path) as source:
                    lines = source.read().splitlines()
                relpath = os.path.relpath(path, package_dir)
                if layer_of_path(relpath) is None and top == 'include' or \
                        relpath.startswith('src/core/') and layer_of_path(relpath) is None:
                    messages.append('%s: in no layer\'s folder (%s)' % (
                        relpath, ', '.join(FOLDER_LAYERS)))
                    continue
                messages += [message for _, _, message in violations(relpath, lines)]
    return messages
