#ifndef BULLET_SIM_TEXTURED_MESH_H
#define BULLET_SIM_TEXTURED_MESH_H

#include <string>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// Writes `geometry` (a box or a finite plane) painted with `texture` as a Wavefront OBJ
/// with its MTL, the image linked beside them, in `folder` (created if needed), so that a
/// viewer that reads meshes (RViz's MESH_RESOURCE markers) draws it textured. Texture
/// coordinates are the camera's (Gazebo's unit_box and unit_plane, through the texture's
/// UV transform), so RViz and the camera show the same image the same way up. A file is
/// written once: the name is a hash of everything it holds.
/// @returns the OBJ's path; "" when it cannot be written (`reason` says why).
std::string writeTexturedMesh(const Geometry& geometry, const TextureRef& texture,
                              const std::string& folder, std::string* reason);

}  // namespace bullet_sim

#endif  // BULLET_SIM_TEXTURED_MESH_H
