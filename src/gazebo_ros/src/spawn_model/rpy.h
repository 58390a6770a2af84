// Orientation of URDF's and Gazebo's rpy.
#pragma once

namespace gazebo_ros_spawn {

struct Quaternion {
  double x, y, z, w;
};

/// The fixed-axis rotation roll about x, then pitch about y, then yaw about z.
Quaternion quaternionFromRpy(double roll, double pitch, double yaw);

}  // namespace gazebo_ros_spawn
