#ifndef BULLET_SIM_CORE_SDF_URDF_CONVERT_H
#define BULLET_SIM_CORE_SDF_URDF_CONVERT_H

#include <Eigen/Geometry>
#include <urdf_model/pose.h>

namespace bullet_sim {

/// An isometry as a URDF pose.
urdf::Pose toUrdfPose(const Eigen::Isometry3d& T);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_URDF_CONVERT_H
