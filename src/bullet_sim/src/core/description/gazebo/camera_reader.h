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

constexpr const char* kTriggeredCameraPlugin = "libgazebo_ros_triggered_camera.so";
constexpr const char* kTriggeredMultiCameraPlugin = "libgazebo_ros_triggered_multicamera.so";

/// The format name of `format` among R8G8B8, B8G8R8, L8, R16G16B16, L16 (Gazebo's aliases
/// RGB_INT8 ... L_INT16 read as these), or "" for another.
std::string canonicalFormat(const std::string& format);

/// The camera part of a camera or depth sensor; the topics default to the plugin's.
CameraSpec readCamera(const SensorElement& sensor, const XmlValues& xml,
                      const std::string& image_topic, const std::string& info_topic);

/// Reads a camera <sensor> with its libgazebo_ros_camera.so plugin into spec->cameras.
void readCameraSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

/// Reads a multicamera <sensor> with libgazebo_ros_(triggered_)multicamera.so: each
/// <camera> whose name holds "left" or "right" becomes a camera under <cameraName>/left or
/// /right (Gazebo's plugin publishes no other), posed at the sensor's pose then its own.
void readMultiCameraSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

/// Reads a wideanglecamera <sensor> (camera and <lens>) into spec->cameras.
void readWideAngleCameraSensor(const SensorElement& sensor, const XmlValues& xml,
                               RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_CAMERA_READER_H
