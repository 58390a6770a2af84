#!/usr/bin/python3
"""`xacro.py`, the name the xacro command had until Melodic (xacro 1.13): launch files of the
Kinetic and Melodic era call `$(find xacro)/xacro.py`. It runs the `xacro` command next to
this file with the same arguments and, as Melodic's did, warns once the output is written:
"xacro.py is deprecated; please use xacro instead" on stderr (in yellow on a terminal,
after "warning: " otherwise). When xacro fails (exit 2) or only prints its usage, it exits as
xacro does, without the warning."""
import importlib.machinery
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.realpath(__file__))


def load_xacro_command():
    """The `xacro` script of this folder as a module: it sets up Debian's Python for the
    PyPI xacro, takes this folder out of sys.path (where this file would be found as the
    module `xacro`) and imports xacro."""
    loader = importlib.machinery.SourceFileLoader('xacro_command', os.path.join(HERE, 'xacro'))
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module


if __name__ == '__main__':
    command = load_xacro_command()
    status = command.xacro.main()
    from xacro.color import warning
    warning('xacro.py is deprecated; please use xacro instead')
    sys.exit(status)
