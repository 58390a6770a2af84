#ifndef BULLET_SIM_CORE_PLANAR_ODOMETRY_H
#define BULLET_SIM_CORE_PLANAR_ODOMETRY_H

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// libgazebo_ros_planar_move.so's odometry (Noetic's formulas): the model's world pose,
/// frame <odometryFrame>, child <robotBaseFrame>; the twist is the difference to the
/// previous reading: (x, y) moved over the time between, turned into the model's yaw frame,
/// and the yaw turned (wrapped to +-pi) over that time, or the commanded yaw rate when that
/// exceeds pi per interval. Pose covariance diagonal 1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3;
/// twist covariance zero.
class PlanarOdometry {
 public:
  /// The reading before the first: the model at `T_world_model` at `time_s` (its spawn).
  void start(const Eigen::Isometry3d& T_world_model, double time_s);
  /// The reading at `time_s`, which becomes the previous one. Two readings at one time
  /// repeat the last twist.
  OdometryData read(const PlanarMoveSpec& spec, const Eigen::Isometry3d& T_world_model,
                    double commanded_yaw_radps, double time_s);

 private:
  Eigen::Isometry3d last_pose_ = Eigen::Isometry3d::Identity();
  double last_time_s_ = 0;
  Twist3 last_twist_;  ///< in the child frame
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PLANAR_ODOMETRY_H
