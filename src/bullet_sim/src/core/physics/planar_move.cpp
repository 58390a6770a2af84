#include "physics/planar_move.h"

#include <cmath>

namespace bullet_sim {

Twist3 planarMoveVelocity(double x_mps, double y_mps, double yaw_radps, double model_yaw_rad) {
  const double c = std::cos(model_yaw_rad), s = std::sin(model_yaw_rad);
  Twist3 v;
  v.linear = Eigen::Vector3d(x_mps * c - y_mps * s, y_mps * c + x_mps * s, 0);
  v.angular = Eigen::Vector3d(0, 0, yaw_radps);
  return v;
}

void PlanarMoveDrive::setCommand(double x_mps, double y_mps, double yaw_radps, double time_s) {
  x_mps_ = x_mps;
  y_mps_ = y_mps;
  yaw_radps_ = yaw_radps;
  last_command_s_ = time_s;
}

void PlanarMoveDrive::update(PhysicsRobot* robot, double model_yaw_rad, double time_s) {
  if (cmd_timeout_s_ >= 0 && time_s - last_command_s_ > cmd_timeout_s_) {
    x_mps_ = y_mps_ = yaw_radps_ = 0;
  }
  robot->setBodyVelocities(planarMoveVelocity(x_mps_, y_mps_, yaw_radps_, model_yaw_rad));
}

}  // namespace bullet_sim
