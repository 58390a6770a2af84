#include "diff_drive.h"

#include <algorithm>
#include <cmath>

namespace bullet_sim {
namespace {

/// Below this rim-speed error (m/s) the plugin jumps straight to the target.
constexpr double kSnapMps = 0.01;

}  // namespace

DiffDriveController::DiffDriveController(const DiffDriveSpec& spec, size_t left_joint,
                                         size_t right_joint, double left_max_radps,
                                         double right_max_radps)
    : spec_(spec), joints_{left_joint, right_joint}, max_radps_{left_max_radps, right_max_radps} {}

double DiffDriveController::setCommand(double linear_mps, double angular_radps) {
  const double radius_m = spec_.wheel_diameter_m / 2.0;
  const double half_track = spec_.wheel_separation_m / 2.0;
  const double wheel_radps[2] = {(linear_mps - angular_radps * half_track) / radius_m,
                                 (linear_mps + angular_radps * half_track) / radius_m};
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
  const double radius_m = spec_.wheel_diameter_m / 2.0;
  const double half_track = spec_.wheel_separation_m / 2.0;
  const double target[2] = {command_v_ - command_w_ * half_track,
                            command_v_ + command_w_ * half_track};
  const double dt = std::max(time_s - last_update_s_, physics_dt_s);
  last_update_s_ = time_s;
  for (int side = 0; side < 2; ++side) {
    const double current = robot->jointVelocity(joints_[side]) * radius_m;
    const double error = target[side] - current;
    if (spec_.wheel_acceleration == 0 || std::fabs(error) < kSnapMps) {
      instructed_mps_[side] = target[side];
    } else {
      const double max_change = spec_.wheel_acceleration * dt;
      instructed_mps_[side] += std::clamp(error, -max_change, max_change);
    }
    robot->setJointMotor(joints_[side], instructed_mps_[side] / radius_m, spec_.wheel_torque_nm);
  }
}

void DiffDriveController::integrateEncoder(const PhysicsRobot& robot, double dt_s) {
  const double radius_m = spec_.wheel_diameter_m / 2.0;
  const double left = robot.jointVelocity(joints_[0]) * radius_m * dt_s;
  const double right = robot.jointVelocity(joints_[1]) * radius_m * dt_s;
  const double mean = (left + right) / 2.0;
  const double dtheta = (right - left) / spec_.wheel_separation_m;
  const double mid_heading = encoder_pose_.z() + dtheta / 2.0;
  encoder_pose_.x() += mean * std::cos(mid_heading);
  encoder_pose_.y() += mean * std::sin(mid_heading);
  encoder_pose_.z() += dtheta;
  encoder_v_ = mean / dt_s;
  encoder_w_ = dtheta / dt_s;
}

void DiffDriveController::reset() {
  command_v_ = command_w_ = 0;
  instructed_mps_[0] = instructed_mps_[1] = 0;
  last_update_s_ = 0;
  encoder_pose_.setZero();
  encoder_v_ = encoder_w_ = 0;
}

}  // namespace bullet_sim
