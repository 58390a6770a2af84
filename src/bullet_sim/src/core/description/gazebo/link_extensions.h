#ifndef BULLET_SIM_CORE_LINK_EXTENSIONS_H
#define BULLET_SIM_CORE_LINK_EXTENSIONS_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// <gazebo reference="link"> <mu1>, <mu2>, <kp>, <kd> into spec->surfaces[link], when any
/// is given. @throws LoadError for a malformed value or a negative friction coefficient.
void readLinkSurface(const tinyxml2::XMLElement* gazebo, const std::string& link,
                     const XmlValues& xml, RobotSpec* spec);

/// <gazebo reference="link"><material>Gazebo/Red</material>: Gazebo draws every visual
/// of the link in that material, whatever the URDF <material> says; an unknown name is
/// drawn grey, with a warning.
void readLinkMaterial(const tinyxml2::XMLElement* gazebo, const std::string& link,
                      const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_LINK_EXTENSIONS_H
