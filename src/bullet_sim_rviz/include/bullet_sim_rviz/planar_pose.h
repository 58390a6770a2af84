#ifndef BULLET_SIM_RVIZ_PLANAR_POSE_H
#define BULLET_SIM_RVIZ_PLANAR_POSE_H

#include <Eigen/Geometry>

namespace bullet_sim_rviz {

/// A position on the ground and a heading about +z, as the place tool picks them.
struct PlanarPose {
  double x_m = 0, y_m = 0, yaw_rad = 0;
};

/// A pose picked in RViz's fixed frame, expressed in the world frame. `T_fixed_world` is the
/// world frame's pose in the fixed frame (what tf says); the heading is the picked direction
/// projected on the world's ground plane, so a tilted fixed frame still gives a level pose.
PlanarPose toWorld(const PlanarPose& in_fixed, const Eigen::Isometry3d& T_fixed_world);

}  // namespace bullet_sim_rviz

#endif  // BULLET_SIM_RVIZ_PLANAR_POSE_H
