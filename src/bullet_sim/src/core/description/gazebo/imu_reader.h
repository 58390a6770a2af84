#ifndef BULLET_SIM_CORE_IMU_READER_H
#define BULLET_SIM_CORE_IMU_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_values.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads an imu <sensor> with its libgazebo_ros_imu_sensor.so plugin into spec->imus.
/// @throws LoadError for a malformed value.
void readImuSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

/// Reads a libgazebo_ros_imu.so model <plugin> (`where` names it), which publishes the IMU of
/// link <bodyName>, into spec->imus.
/// @throws LoadError for a missing <bodyName> or a malformed value.
void readImuPlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                   const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_IMU_READER_H
