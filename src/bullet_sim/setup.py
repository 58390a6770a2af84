from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

# The pure-Python part of the bullet_sim package; its compiled _core is built and installed
# by CMakeLists.txt.
setup(**generate_distutils_setup(
    packages=['bullet_sim', 'bullet_sim.envs'],
    package_dir={'': 'python'},
    package_data={'bullet_sim': ['py.typed', '*.pyi']}))
