from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=['mobility_image_view'], package_dir={'': 'src'}))
