# Python's distutils from the standard library (python3-distutils, which ROS's rosclean
# depends on) rather than setuptools' copy of it: roslaunch imports distutils through
# rosclean, and setuptools' copy brings all of setuptools with it, 0.12 s at every start
# of roslaunch and roscore. A value the user has set is kept.
if [ -z "${SETUPTOOLS_USE_DISTUTILS:-}" ]; then
  export SETUPTOOLS_USE_DISTUTILS=stdlib
fi
