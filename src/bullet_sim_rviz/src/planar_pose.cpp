#include "bullet_sim_rviz/planar_pose.h"

#include <cmath>

namespace bullet_sim_rviz {

PlanarPose toWorld(const PlanarPose& in_fixed, const Eigen::Isometry3d& T_fixed_world) {
  const Eigen::Isometry3d T_world_fixed = T_fixed_world.inverse();
  const Eigen::Vector3d p = T_world_fixed * Eigen::Vector3d(in_fixed.x_m, in_fixed.y_m, 0);
  const Eigen::Vector3d heading =
      T_world_fixed.linear() *
      Eigen::Vector3d(std::cos(in_fixed.yaw_rad), std::sin(in_fixed.yaw_rad), 0);
  return {p.x(), p.y(), std::atan2(heading.y(), heading.x())};
}

}  // namespace bullet_sim_rviz
