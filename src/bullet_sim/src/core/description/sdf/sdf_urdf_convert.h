#ifndef BULLET_SIM_CORE_SDF_URDF_CONVERT_H
#define BULLET_SIM_CORE_SDF_URDF_CONVERT_H

#include <Eigen/Geometry>
#include <sdf/sdf.hh>
#include <urdf_model/pose.h>

namespace bullet_sim {

/// An SDF pose as an isometry.
Eigen::Isometry3d sdfToIsometry(const ignition::math::Pose3d& p);

/// An isometry as a URDF pose.
urdf::Pose toUrdfPose(const Eigen::Isometry3d& T);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_URDF_CONVERT_H
