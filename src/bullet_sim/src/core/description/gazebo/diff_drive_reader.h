#ifndef BULLET_SIM_CORE_DIFF_DRIVE_READER_H
#define BULLET_SIM_CORE_DIFF_DRIVE_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// Reads a libgazebo_ros_diff_drive.so model <plugin> (`where` names it) into
/// spec->diff_drive: the wheel joints, topics, frames, wheel figures and what it publishes.
/// @throws LoadError for a second diff drive, a missing joint or a value out of range.
void readDiffDrivePlugin(const tinyxml2::XMLElement* plugin, const std::string& where,
                         const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_DIFF_DRIVE_READER_H
