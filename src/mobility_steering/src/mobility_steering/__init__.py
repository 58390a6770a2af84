"""Steering window and terminal teleop: ROS-free logic plus thin ROS and Qt adapters."""
