#ifndef BULLET_SIM_CORE_DIFF_DRIVE_H
#define BULLET_SIM_CORE_DIFF_DRIVE_H

#include <vector>

#include <Eigen/Core>

#include "bullet_sim/description/robot_spec.h"
#include "physics/diff_drive_kinematics.h"
#include "physics/physics_robot.h"

namespace bullet_sim {

/// The libgazebo_ros_diff_drive.so and libgazebo_ros_skid_steer_drive.so behaviour: turns
/// (v, w) into wheel velocity motors at the plugin's update rate (every wheel of a side
/// turns at that side's speed: a skid steer's front and rear wheel alike), ramping the commanded rim speed by at
/// most wheelAcceleration * dt per update, with wheelTorque as the motor limit;
/// and integrates encoder odometry from the wheel joint speeds. A command that would turn a
/// wheel faster than its joint's <limit velocity> is scaled down whole, as a real base
/// controller does: both wheels slow by the same factor, so the turn radius stays.
class DiffDriveController {
 public:
  /// `left_joints` / `right_joints`: each side's wheel joints, the first the one whose
  /// speed the ramp and the encoder odometry read; `left_max_radps` / `right_max_radps`:
  /// the lowest velocity limit among a side's joints (infinity for none).
  DiffDriveController(const DiffDriveSpec& spec, std::vector<size_t> left_joints,
                      std::vector<size_t> right_joints, double left_max_radps,
                      double right_max_radps);

  /// Sets the command the motors follow from the next update.
  /// @return the factor (<= 1) it was scaled by to keep both wheels within their limits.
  double setCommand(double linear_mps, double angular_radps);
  /// Updates the wheel motors (call at the plugin's update steps).
  void updateMotors(PhysicsRobot* robot, double time_s, double physics_dt_s);
  /// Integrates encoder odometry over one physics step.
  void integrateEncoder(const PhysicsRobot& robot, double dt_s);
  /// Back to rest: zero command, zero encoder pose.
  void reset();

  /// Encoder odometry: x, y (m), heading (rad) in the odometry frame.
  const Eigen::Vector3d& encoderPose() const { return encoder_pose_; }
  double encoderLinearMps() const { return encoder_v_; }
  double encoderAngularRadps() const { return encoder_w_; }

 private:
  DiffDriveSpec spec_;
  DiffDriveKinematics kinematics_;
  std::vector<size_t> joints_[2];
  double max_radps_[2];
  double command_v_ = 0, command_w_ = 0;
  double instructed_mps_[2] = {0, 0};  ///< rim speeds given to the motors
  double last_update_s_ = 0;
  Eigen::Vector3d encoder_pose_{0, 0, 0};
  double encoder_v_ = 0, encoder_w_ = 0;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_DIFF_DRIVE_H
