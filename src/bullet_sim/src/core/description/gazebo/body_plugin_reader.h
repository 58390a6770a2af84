#ifndef BULLET_SIM_CORE_BODY_PLUGIN_READER_H
#define BULLET_SIM_CORE_BODY_PLUGIN_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

// Model plugins that name one link (<bodyName>) and one topic (<topicName>).

/// Reads a libgazebo_ros_p3d.so model <plugin> (`where` names it) into spec->p3ds: <bodyName>
/// and <topicName> (both required, as in Gazebo), <frameName> (world), <xyzOffset> and
/// <rpyOffset> (0 0 0), <gaussianNoise> (0), <updateRate> (0: every step).
/// @throws LoadError for a missing body or topic, or a value that is not a number.
void readP3dPlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                   const XmlValues& xml, RobotSpec* spec);

/// Reads a libgazebo_ros_force.so model <plugin> into spec->forces: <bodyName> and
/// <topicName>, both required (Gazebo's plugin does not load without them).
/// @throws LoadError naming the missing element.
void readForcePlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                     const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_BODY_PLUGIN_READER_H
