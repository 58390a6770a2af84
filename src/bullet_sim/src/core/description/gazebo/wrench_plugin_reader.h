#ifndef BULLET_SIM_CORE_WRENCH_PLUGIN_READER_H
#define BULLET_SIM_CORE_WRENCH_PLUGIN_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

// Model plugins that publish a geometry_msgs/WrenchStamped.

/// Reads a libgazebo_ros_f3d.so model <plugin> (`where` names it) into spec->f3ds:
/// <bodyName> and <topicName> (both required, as in Gazebo), <frameName> (world).
/// @throws LoadError naming a missing element.
void readF3dPlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                   const XmlValues& xml, RobotSpec* spec);

/// Reads a libgazebo_ros_ft_sensor.so model <plugin> into spec->ft_sensors: <jointName>
/// and <topicName> (both required), <gaussianNoise> (0), <updateRate> (0: every step).
/// @throws LoadError for a missing element, or a value that is not a number or is < 0.
void readFtSensorPlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                        const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_WRENCH_PLUGIN_READER_H
