#ifndef BULLET_SIM_CORE_SKID_STEER_READER_H
#define BULLET_SIM_CORE_SKID_STEER_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a libgazebo_ros_skid_steer_drive.so model <plugin> (`where` names it) into
/// spec->diff_drive, with the skid steer's names and defaults (Noetic's gazebo_plugins):
/// <leftFrontJoint> left_front_joint, <rightFrontJoint> right_front_joint, <leftRearJoint>
/// left_rear_joint, <rightRearJoint> right_rear_joint, <wheelSeparation> 0.4,
/// <wheelDiameter> 0.15, <torque> 5, <commandTopic> cmd_vel, <odometryTopic> odom,
/// <odometryFrame> odom, <robotBaseFrame> base_footprint, <updateRate> 100,
/// <broadcastTF> false, <covariance_x> 0.0001, <covariance_y> 0.0001, <covariance_yaw> 0.01.
/// Its odometry is the model's world pose; its wheels take the commanded speed at once
/// (no acceleration limit).
/// @throws LoadError for a second drive plugin or a value out of range.
void readSkidSteerDrivePlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                              const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SKID_STEER_READER_H
