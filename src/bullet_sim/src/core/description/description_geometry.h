#ifndef BULLET_SIM_CORE_DESCRIPTION_GEOMETRY_H
#define BULLET_SIM_CORE_DESCRIPTION_GEOMETRY_H

#include <optional>

#include <urdf_model/link.h>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// The Geometry of a URDF <geometry> as urdfdom read it: box, cylinder, sphere, or mesh
/// (its filename as written and its scale).
Geometry geometryOf(const urdf::Geometry& geometry);

/// The urdfdom geometry of a box, cylinder, sphere or mesh (a plane has none in URDF:
/// null), as a movable SDF model's links are written into its URDF model.
urdf::GeometrySharedPtr urdfGeometry(const Geometry& geometry);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_DESCRIPTION_GEOMETRY_H
