#ifndef BULLET_SIM_CORE_SDF_UTIL_H
#define BULLET_SIM_CORE_SDF_UTIL_H

#include <string>
#include <vector>

#include <Eigen/Core>
#include <sdf/sdf.hh>

#include "bullet_sim/types.h"

namespace bullet_sim {

Pose3 toPose(const ignition::math::Pose3d& p);
ignition::math::Pose3d toSdfPose(const Pose3& p);

/// Pose of an SDF element in its parent's frame (relative_to honoured when it resolves).
template <typename T>
ignition::math::Pose3d poseInParent(const T& element) {
  ignition::math::Pose3d pose;
  if (!element.SemanticPose().Resolve(pose).empty()) pose = element.RawPose();
  return pose;
}

/// "box", "mesh", ... for messages.
std::string geometryName(sdf::GeometryType type);

/// A box size, cylinder radius or length, or sphere radius that is negative or not finite
/// (libsdformat takes them as written) cannot be simulated or drawn.
/// @throws LoadError "`where`: <box> <size>: '1 -0.5 0.3' ..." naming the value.
void checkGeometrySize(const sdf::Geometry& geometry, const std::string& where);

/// The colour a visual is drawn with, as Gazebo shows it: an explicit <diffuse> wins over a
/// <script> material name, which wins over an <ambient>, then the default grey. An unknown
/// script name adds a warning naming it (`where` says whose visual it is; none when
/// `warnings` is null). visual_appearance.h adds the scripts of the visual's own files.
Eigen::Vector4f visualColour(const sdf::Visual& visual, const std::string& where,
                             std::vector<std::string>* warnings);

/// libsdformat's errors joined with "; ".
std::string describe(const sdf::Errors& errors);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_UTIL_H
