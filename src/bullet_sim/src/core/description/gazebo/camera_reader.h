#ifndef BULLET_SIM_CORE_CAMERA_READER_H
#define BULLET_SIM_CORE_CAMERA_READER_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_values.h"
#include "description/xml_values.h"

namespace bullet_sim {

/// A camera's <camera> values that no renderer can use are load errors. A wide-angle
/// camera's horizontal fov may reach 2 pi, a pinhole's stays below pi.
/// @throws LoadError naming `where` + the element and its value.
void checkCameraValues(const tinyxml2::XMLElement* sensor, const std::string& where,
                       const XmlValues& xml, bool wide_angle = false);

/// The camera part of a camera or depth sensor; the topics default to the plugin's.
CameraSpec readCamera(const SensorElement& sensor, const XmlValues& xml,
                      const std::string& image_topic, const std::string& info_topic);

/// Reads a camera <sensor> with its libgazebo_ros_camera.so plugin into spec->cameras.
void readCameraSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

/// Reads a wideanglecamera <sensor> (camera and <lens>) into spec->cameras.
void readWideAngleCameraSensor(const SensorElement& sensor, const XmlValues& xml,
                               RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_CAMERA_READER_H
