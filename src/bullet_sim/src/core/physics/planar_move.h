#ifndef BULLET_SIM_CORE_PLANAR_MOVE_H
#define BULLET_SIM_CORE_PLANAR_MOVE_H

#include "bullet_sim/types.h"
#include "physics/physics_robot.h"

namespace bullet_sim {

/// The velocity libgazebo_ros_planar_move.so gives every link of its model at the start of
/// a step: the command's (x, y) turned by the model's yaw, z 0; angular (0, 0, yaw rate).
Twist3 planarMoveVelocity(double x_mps, double y_mps, double yaw_radps, double model_yaw_rad);

/// libgazebo_ros_planar_move.so's drive: the last command, given to the model at every
/// step until <cmdTimeout> passes without a new one.
class PlanarMoveDrive {
 public:
  /// `cmd_timeout_s` < 0: a command holds until the next.
  explicit PlanarMoveDrive(double cmd_timeout_s) : cmd_timeout_s_(cmd_timeout_s) {}

  void setCommand(double x_mps, double y_mps, double yaw_radps, double time_s);
  /// At the start of a step at `time_s`: zeroes a command older than the timeout (as
  /// Gazebo, strictly older), then sets every body's velocity (planarMoveVelocity).
  void update(PhysicsRobot* robot, double model_yaw_rad, double time_s);
  /// The yaw rate commanded now (the odometry reports it when the turn between two
  /// readings is beyond what it can tell).
  double yawRateRadps() const { return yaw_radps_; }
  /// No command (a world reset).
  void reset() { x_mps_ = y_mps_ = yaw_radps_ = last_command_s_ = 0; }

 private:
  double cmd_timeout_s_;
  double x_mps_ = 0, y_mps_ = 0, yaw_radps_ = 0, last_command_s_ = 0;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PLANAR_MOVE_H
