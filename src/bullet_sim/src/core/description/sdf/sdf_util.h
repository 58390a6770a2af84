#ifndef BULLET_SIM_CORE_SDF_UTIL_H
#define BULLET_SIM_CORE_SDF_UTIL_H

#include <string>
#include <vector>

#include <Eigen/Core>

#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// A box size, cylinder radius or length, or sphere radius that is negative or not finite
/// (SDF takes them as written) cannot be simulated or drawn.
/// @throws LoadError "`where`: <box> <size>: '1 -0.5 0.3' ..." naming the value.
void checkGeometrySize(const SdfGeometry& geometry, const std::string& where);

/// The colour a visual is drawn with, as Gazebo shows it: an explicit <diffuse> wins over a
/// <script> material name, which wins over an <ambient>, then the default grey. An unknown
/// script name adds a warning naming it (`where` says whose visual it is; none when
/// `warnings` is null). visual_appearance.h adds the scripts of the visual's own files.
Eigen::Vector4f visualColour(const SdfVisual& visual, const std::string& where,
                             std::vector<std::string>* warnings);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_UTIL_H
