#ifndef BULLET_SIM_CORE_RAY_READER_H
#define BULLET_SIM_CORE_RAY_READER_H

#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_values.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a ray or gpu_ray <sensor> with its laser plugin into spec->rays: the pose, rate,
/// <ray><scan><horizontal>, <ray><range> and <ray><noise>, the plugin's topic and frame.
/// @throws LoadError for a missing <horizontal> or <range>, or a value out of range.
void readRaySensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_RAY_READER_H
