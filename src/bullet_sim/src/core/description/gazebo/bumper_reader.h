#ifndef BULLET_SIM_CORE_BUMPER_READER_H
#define BULLET_SIM_CORE_BUMPER_READER_H

#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_values.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a <sensor type="contact"> with libgazebo_ros_bumper.so into spec->bumpers: its
/// rate, the <contact><collision> it watches, the plugin's bumperTopicName and frameName.
/// @throws LoadError for a missing <contact><collision> or a bad rate.
void readBumperSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_BUMPER_READER_H
