#ifndef BULLET_SIM_CORE_GAZEBO_EXTENSIONS_H
#define BULLET_SIM_CORE_GAZEBO_EXTENSIONS_H

#include <string>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// Reads the <gazebo> extension tags of a URDF document (surfaces, sensors,
/// plugins, material scripts) into `spec`; unsupported sensors and plugins become
/// warnings. A link's <material> recolours its visuals: spec->visuals must be filled.
/// @throws LoadError on malformed values.
void parseGazeboExtensions(const std::string& urdf_xml, const std::string& source,
                           RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_GAZEBO_EXTENSIONS_H
