#include "physics/diff_drive_kinematics.h"

#include <cmath>

namespace bullet_sim {

Eigen::Vector2d DiffDriveKinematics::wheelVelocities(double linear_mps,
                                                     double angular_radps) const {
  const double half_track_mps = angular_radps * wheel_separation_m / 2.0;
  return Eigen::Vector2d(linear_mps - half_track_mps, linear_mps + half_track_mps) /
         wheel_radius_m;
}

Eigen::Vector2d DiffDriveKinematics::baseVelocities(double left_radps,
                                                    double right_radps) const {
  return Eigen::Vector2d(wheel_radius_m * (left_radps + right_radps) / 2.0,
                         wheel_radius_m * (right_radps - left_radps) / wheel_separation_m);
}

Eigen::Vector3d advancePose(const Eigen::Vector3d& pose, double distance_m, double turn_rad) {
  const double mid_heading = pose.z() + turn_rad / 2.0;
  return Eigen::Vector3d(pose.x() + distance_m * std::cos(mid_heading),
                         pose.y() + distance_m * std::sin(mid_heading), pose.z() + turn_rad);
}

}  // namespace bullet_sim
