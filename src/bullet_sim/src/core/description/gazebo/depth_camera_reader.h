#ifndef BULLET_SIM_CORE_DEPTH_CAMERA_READER_H
#define BULLET_SIM_CORE_DEPTH_CAMERA_READER_H

#include "bullet_sim/description/robot_spec.h"
#include "description/gazebo/gazebo_values.h"
#include "description/xml_values.h"

namespace bullet_sim {

constexpr const char* kKinectPlugin = "libgazebo_ros_openni_kinect.so";
constexpr const char* kDepthCameraPlugin = "libgazebo_ros_depth_camera.so";

/// Reads a depth <sensor> with one of Gazebo's depth plugins into spec->cameras. They
/// publish the colour image as a camera does (under ir/ unless told otherwise), plus depth
/// image, its camera_info and the point cloud; only the kinect plugin has an upper cutoff.
/// @throws LoadError for a camera or cutoff value out of range.
void readDepthCameraSensor(const SensorElement& sensor, const XmlValues& xml, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_DEPTH_CAMERA_READER_H
