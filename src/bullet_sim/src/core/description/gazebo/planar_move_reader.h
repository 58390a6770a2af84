#ifndef BULLET_SIM_CORE_PLANAR_MOVE_READER_H
#define BULLET_SIM_CORE_PLANAR_MOVE_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a libgazebo_ros_planar_move.so model <plugin> (`where` names it) into
/// spec->planar_move, with the plugin's names and defaults (Noetic's gazebo_plugins):
/// <commandTopic> cmd_vel, <odometryTopic> odom, <odometryFrame> odom, <robotBaseFrame>
/// base_footprint, <odometryRate> 20 (0: no odometry), <cmdTimeout> -1 (never).
/// @throws LoadError for a second planar move plugin, a rate that is not a number >= 0 or
/// a timeout that is not a number.
void readPlanarMovePlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                          const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PLANAR_MOVE_READER_H
