#include "description/gazebo/planar_move_reader.h"

#include <cmath>

#include "description/gazebo/gazebo_values.h"

namespace bullet_sim {

void readPlanarMovePlugin(const tinyxml2::XMLElement* p, const std::string& where,
                          const XmlValues& xml, RobotSpec* spec) {
  if (spec->planar_move) xml.fail(where, "a second libgazebo_ros_planar_move.so plugin");
  PlanarMoveSpec s;
  s.command_topic = xml.text(p, "commandTopic", s.command_topic);
  s.odometry_topic = xml.text(p, "odometryTopic", s.odometry_topic);
  s.odometry_frame = xml.text(p, "odometryFrame", s.odometry_frame);
  s.robot_base_frame = xml.text(p, "robotBaseFrame", s.robot_base_frame);
  s.odometry_rate_hz = readRate(xml, p, "odometryRate", s.odometry_rate_hz, where);
  s.cmd_timeout_s = xml.number(p, "cmdTimeout", s.cmd_timeout_s, where);
  if (std::isnan(s.cmd_timeout_s)) {
    xml.fail(where + " <cmdTimeout>", "'" + xml.text(p, "cmdTimeout", "") + "' is not a number");
  }
  spec->planar_move = s;
}

}  // namespace bullet_sim
