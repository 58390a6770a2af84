#ifndef BULLET_SIM_CORE_MULTI_RAY_READER_H
#define BULLET_SIM_CORE_MULTI_RAY_READER_H

#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_values.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a ray <sensor> with libgazebo_ros_range.so into spec->ranges: its <ray> (horizontal
/// and vertical <scan>, <range>), pose and rate, and the plugin's topicName, frameName,
/// radiation, fov, gaussianNoise and updateRate.
/// @throws LoadError for a missing <horizontal> or <range>, or a value out of range.
void readRangeSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

/// Reads a ray <sensor> with libgazebo_ros_block_laser.so into spec->block_lasers: its
/// <ray>, pose and rate, and the plugin's topicName, frameName and gaussianNoise.
/// @throws LoadError as readRangeSensor.
void readBlockLaserSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_MULTI_RAY_READER_H
