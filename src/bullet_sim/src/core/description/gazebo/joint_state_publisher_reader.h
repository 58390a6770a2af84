#ifndef BULLET_SIM_CORE_JOINT_STATE_PUBLISHER_READER_H
#define BULLET_SIM_CORE_JOINT_STATE_PUBLISHER_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a libgazebo_ros_joint_state_publisher.so model <plugin> into
/// spec->joint_state_publishers: <jointName> (a comma-separated list; white space is
/// dropped, as Gazebo drops the spaces) and <updateRate> (100; 0: every step). Without
/// <jointName> the plugin publishes no joints, as Gazebo's does (a warning says so).
/// @throws LoadError naming the plugin, the element and the value for an empty name in the
/// list, a joint the model does not have, or a rate that is not a number >= 0.
void readJointStatePublisherPlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                                   const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_JOINT_STATE_PUBLISHER_READER_H
