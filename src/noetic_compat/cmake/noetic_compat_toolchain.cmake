# noetic_compat's settings for CMake projects configured in a shell where this workspace's
# setup.bash was sourced (its env hook exports CMAKE_TOOLCHAIN_FILE, which CMake reads when
# it configures a new build folder). Each line removes one failure of unmodified Noetic
# sources on Debian 12; see noetic_compat's README. The file lies in the package's source
# folder (devel space) or its share folder (install space), include_compat/ beside cmake/.

# Headers Debian dropped ("pluginlib/class_list_macros.h: No such file or directory"):
# forwarding headers, searched after every other include folder.
get_filename_component(_noetic_compat_include "${CMAKE_CURRENT_LIST_DIR}/../include_compat" ABSOLUTE)
# Boost's global placeholders ("'_1' was not declared in this scope").
set(CMAKE_CXX_FLAGS_INIT
    "-idirafter ${_noetic_compat_include} -include ${_noetic_compat_include}/noetic_compat/global_placeholders.h")

# Libraries a program uses but links only through another library
# ("libboost_program_options.so...: error adding symbols: DSO missing from command line"):
# the linker also searches the libraries that the linked libraries need, as it used to.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-Wl,--copy-dt-needed-entries")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-Wl,--copy-dt-needed-entries")
set(CMAKE_MODULE_LINKER_FLAGS_INIT "-Wl,--copy-dt-needed-entries")

# The Python 3 of Debian's ROS modules, whatever python3 comes first in PATH (catkin's
# PYTHON_EXECUTABLE: "No module named 'catkin_pkg'"; FindPython3 for Debian's ament-built
# angles: "No module named 'ament_package'"). Debian's ROS modules are installed for
# /usr/bin/python3 only. A value given with -D is kept. Debian 12's catkin (0.8.10-9)
# takes PYTHON_EXECUTABLE; Debian 13's (0.8.10-17) finds its interpreter with FindPython
# and sets PYTHON_EXECUTABLE to Python_EXECUTABLE, which therefore follows it here.
set(PYTHON_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter (noetic_compat)")
set(Python_EXECUTABLE ${PYTHON_EXECUTABLE} CACHE FILEPATH "Python interpreter of catkin's FindPython (noetic_compat)")
set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python 3 interpreter (noetic_compat)")
