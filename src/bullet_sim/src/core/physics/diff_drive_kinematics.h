#ifndef BULLET_SIM_CORE_DIFF_DRIVE_KINEMATICS_H
#define BULLET_SIM_CORE_DIFF_DRIVE_KINEMATICS_H

#include <Eigen/Core>

namespace bullet_sim {

/// Kinematics of a differential drive: two wheels of radius `wheel_radius_m` on one axle,
/// `wheel_separation_m` apart, the base's origin midway between them, rolling without slip.
struct DiffDriveKinematics {
  double wheel_separation_m = 0;
  double wheel_radius_m = 0;

  /// Wheel angular velocities (rad/s; left, right) that move the base forward at
  /// `linear_mps` while it turns at `angular_radps` (counter-clockwise positive):
  /// (v - w * separation / 2) / radius and (v + w * separation / 2) / radius.
  Eigen::Vector2d wheelVelocities(double linear_mps, double angular_radps) const;

  /// The base's forward and turn rates (m/s, rad/s) for wheel angular velocities:
  /// radius * (left + right) / 2 and radius * (right - left) / separation.
  Eigen::Vector2d baseVelocities(double left_radps, double right_radps) const;
};

/// A planar pose (x, y in metres, heading in rad) moved `distance_m` forward while it turns
/// by `turn_rad`: along the chord, at the heading halfway through the turn, which follows an
/// arc of constant curvature to within distance * turn^2 / 24.
Eigen::Vector3d advancePose(const Eigen::Vector3d& pose, double distance_m, double turn_rad);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_DIFF_DRIVE_KINEMATICS_H
