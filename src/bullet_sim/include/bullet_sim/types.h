#ifndef BULLET_SIM_TYPES_H
#define BULLET_SIM_TYPES_H

#include <Eigen/Geometry>

namespace bullet_sim {

/// A rigid transform: position in metres and a unit quaternion.
struct Pose3 {
  Eigen::Vector3d position{0, 0, 0};
  Eigen::Quaterniond orientation{1, 0, 0, 0};
};

/// Linear (m/s) and angular (rad/s) velocity, expressed in the world frame.
struct Twist3 {
  Eigen::Vector3d linear{0, 0, 0};
  Eigen::Vector3d angular{0, 0, 0};
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_TYPES_H
