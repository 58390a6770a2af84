#include "physics/diff_drive.h"

#include <algorithm>
#include <cmath>

namespace bullet_sim {
namespace {

/// Below this rim-speed error (m/s) the plugin jumps straight to the target.
constexpr double kSnapMps = 0.01;

}  // namespace

DiffDriveController::DiffDriveController(const DiffDriveSpec& spec,
                                         std::vector<size_t> left_joints,
                                         std::vector<size_t> right_joints,
                                         double left_max_radps, double right_max_radps)
    : spec_(spec),
      kinematics_{spec.wheel_separation_m, spec.wheel_diameter_m / 2.0},
      joints_{std::move(left_joints), std::move(right_joints)},
      max_radps_{left_max_radps, right_max_radps} {}

double DiffDriveController::setCommand(double linear_mps, double angular_radps) {
  const Eigen::Vector2d wheel_radps = kinematics_.wheelVelocities(linear_mps, angular_radps);
  double scale = 1.0;
  for (int side = 0; side < 2; ++side) {
    if (std::fabs(wheel_radps[side]) > max_radps_[side]) {
      scale = std::min(scale, max_radps_[side] / std::fabs(wheel_radps[side]));
    }
  }
  // Scaling v and w alike scales both wheel speeds alike: v / w, the turn radius, stays.
  command_v_ = linear_mps * scale;
  command_w_ = angular_radps * scale;
  return scale;
}

void DiffDriveController::updateMotors(PhysicsRobot* robot, double time_s, double physics_dt_s) {
  const double radius_m = kinematics_.wheel_radius_m;
  // The ramp works on rim speeds (m/s), as wheelAcceleration is given.
  const Eigen::Vector2d target = kinematics_.wheelVelocities(command_v_, command_w_) * radius_m;
  const double dt = std::max(time_s - last_update_s_, physics_dt_s);
  last_update_s_ = time_s;
  for (int side = 0; side < 2; ++side) {
    const double current = robot->jointVelocity(joints_[side].front()) * radius_m;
    const double error = target[side] - current;
    if (spec_.wheel_acceleration == 0 || std::fabs(error) < kSnapMps) {
      instructed_mps_[side] = target[side];
    } else {
      const double max_change = spec_.wheel_acceleration * dt;
      instructed_mps_[side] += std::clamp(error, -max_change, max_change);
    }
    for (const size_t joint : joints_[side]) {
      robot->setJointMotor(joint, instructed_mps_[side] / radius_m, spec_.wheel_torque_nm);
    }
  }
}

void DiffDriveController::integrateEncoder(const PhysicsRobot& robot, double dt_s) {
  const Eigen::Vector2d base = kinematics_.baseVelocities(
      robot.jointVelocity(joints_[0].front()), robot.jointVelocity(joints_[1].front()));
  encoder_pose_ = advancePose(encoder_pose_, base[0] * dt_s, base[1] * dt_s);
  encoder_v_ = base[0];
  encoder_w_ = base[1];
}

void DiffDriveController::reset() {
  command_v_ = command_w_ = 0;
  instructed_mps_[0] = instructed_mps_[1] = 0;
  last_update_s_ = 0;
  encoder_pose_.setZero();
  encoder_v_ = encoder_w_ = 0;
}

}  // namespace bullet_sim
