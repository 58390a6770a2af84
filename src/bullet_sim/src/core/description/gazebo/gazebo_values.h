#ifndef BULLET_SIM_CORE_GAZEBO_VALUES_H
#define BULLET_SIM_CORE_GAZEBO_VALUES_H

#include <string>

#include <tinyxml2.h>

#include "description/xml_values.h"

namespace bullet_sim {

/// One <sensor> of a <gazebo reference="link"> block with its ROS <plugin> (null when it has
/// none), as each sensor family's reader takes it; `where` names the sensor in messages.
struct SensorElement {
  const tinyxml2::XMLElement* sensor;
  const tinyxml2::XMLElement* plugin;
  std::string link, name, where;
};

/// The attribute `name` of `e`, "" when it has none.
std::string attribute(const tinyxml2::XMLElement* e, const char* name);

/// An update rate in Hz: 0 means every step, as in Gazebo; a negative one is an error.
/// @throws LoadError naming `where`, the element and its text.
double readRate(const XmlValues& xml, const tinyxml2::XMLElement* parent, const char* name,
                double fallback, const std::string& where);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_GAZEBO_VALUES_H
