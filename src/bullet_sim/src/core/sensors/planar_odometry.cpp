#include "sensors/planar_odometry.h"

#include <cmath>

namespace bullet_sim {

namespace {

/// The yaw of a rotation (about z, of its z-y-x angles), as Gazebo's Rot().Yaw().
double yawOf(const Eigen::Matrix3d& R) { return std::atan2(R(1, 0), R(0, 0)); }

}  // namespace

void PlanarOdometry::start(const Eigen::Isometry3d& T_world_model, double time_s) {
  last_pose_ = T_world_model;
  last_time_s_ = time_s;
  last_twist_ = Twist3();
}

OdometryData PlanarOdometry::read(const PlanarMoveSpec& spec,
                                  const Eigen::Isometry3d& T_world_model,
                                  double commanded_yaw_radps, double time_s) {
  OdometryData odom;
  odom.time_s = time_s;
  odom.frame_id = spec.odometry_frame;
  odom.child_frame_id = spec.robot_base_frame;
  odom.pose.position = T_world_model.translation();
  odom.pose.orientation = Eigen::Quaterniond(T_world_model.linear());
  const double diagonal[6] = {1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3};
  for (int i = 0; i < 6; ++i) odom.pose_covariance[i * 7] = diagonal[i];
  const double dt = time_s - last_time_s_;
  if (dt > 0) {
    const Eigen::Vector2d moved =
        (T_world_model.translation() - last_pose_.translation()).head<2>() / dt;
    const double yaw = yawOf(T_world_model.linear()), last_yaw = yawOf(last_pose_.linear());
    double turned = yaw - last_yaw;
    while (turned < -M_PI) turned += 2 * M_PI;
    while (turned > M_PI) turned -= 2 * M_PI;
    const double c = std::cos(yaw), s = std::sin(yaw);
    last_twist_.linear = Eigen::Vector3d(c * moved.x() + s * moved.y(),
                                         c * moved.y() - s * moved.x(), 0);
    last_twist_.angular = Eigen::Vector3d(
        0, 0, commanded_yaw_radps > M_PI / dt ? commanded_yaw_radps : turned / dt);
    last_pose_ = T_world_model;
    last_time_s_ = time_s;
  }
  odom.twist_in_child = last_twist_;
  return odom;
}

}  // namespace bullet_sim
