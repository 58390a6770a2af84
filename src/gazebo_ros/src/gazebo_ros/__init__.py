"""The workspace's gazebo_ros: Gazebo's ROS 1 launch files, scripts and Python API, served
by bullet_sim instead of gzserver."""
