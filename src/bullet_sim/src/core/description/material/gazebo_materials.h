#ifndef BULLET_SIM_CORE_GAZEBO_MATERIALS_H
#define BULLET_SIM_CORE_GAZEBO_MATERIALS_H

#include <optional>
#include <string>

#include <Eigen/Core>

namespace bullet_sim {

/// The colour a Gazebo material script name stands for (`Gazebo/Grey`, `Gazebo/Wood`, ...):
/// the diffuse colour of Gazebo's stock gazebo.material, or for a textured material the
/// mean colour of its texture. std::nullopt for a name Gazebo does not ship.
std::optional<Eigen::Vector4f> gazeboMaterialColour(const std::string& script_name);

/// The colour drawn for a material script Gazebo does not ship (its grey).
Eigen::Vector4f unknownMaterialColour();

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_GAZEBO_MATERIALS_H
