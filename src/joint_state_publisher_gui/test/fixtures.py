"""Paths of the test URDF files."""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def urdf_text(name):
    """Text of test/urdf/<name>."""
    with open(os.path.join(HERE, 'urdf', name), encoding='utf-8') as f:
        return f.read()
