"""Image viewer for sensor_msgs/Image topics (the workspace's stand-in for rqt_image_view)."""
