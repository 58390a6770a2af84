"""Reads released_types.txt: the md5sums, fields and constants of the released
turtlebot3_msgs that the tests compare with."""
import os

PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'released_types.txt')
# Words on a line, by its first word.
LINE_WIDTH = {'md5': 3, 'field': 4, 'const': 4}


def read(path=PATH):
    """{'md5': [(type, md5)], 'field': [(type, name, field_type)],
    'const': [(type, name, value)]}, in the file's order."""
    table = {kind: [] for kind in LINE_WIDTH}
    with open(path) as source:
        for number, line in enumerate(source, 1):
            words = line.split('#', 1)[0].split()
            if not words:
                continue
            if LINE_WIDTH.get(words[0]) != len(words):
                raise ValueError('%s:%d: cannot read %r' % (path, number, line.strip()))
            table[words[0]].append(tuple(words[1:]))
    return table


def md5sums(table):
    return dict(table['md5'])


def definitions(table):
    """{type: ([(field, field_type)], [(constant, value)])} for every type."""
    return {name: ([(field, kind) for owner, field, kind in table['field'] if owner == name],
                   [(const, value) for owner, const, value in table['const'] if owner == name])
            for name, _ in table['md5']}
