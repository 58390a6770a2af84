#ifndef BULLET_SIM_CORE_SDF_SURFACE_H
#define BULLET_SIM_CORE_SDF_SURFACE_H

#include <string>

#include "bullet_sim/description/robot_spec.h"
#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// Takes Gazebo's friction coefficients of an SDF collision, <surface><friction><ode><mu>
/// and <mu2>, into `surface->mu1` and `mu2`, each where the file gives it (the others keep
/// their values: Gazebo's default is 1).
/// @return whether the collision has a <surface><friction><ode> element.
/// @throws LoadError "`where`: <surface><friction><ode><mu>: 'nan' is not a friction
///         coefficient >= 0".
bool readOdeFriction(const SdfCollision& collision, const std::string& where,
                     SurfaceParams* surface);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_SURFACE_H
