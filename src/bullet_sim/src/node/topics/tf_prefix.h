// Frame names of robots in namespaces, as Gazebo's ROS plugins make them.
#pragma once

#include <ros/node_handle.h>

#include <string>

namespace bullet_sim_node {

/// `frame` under `prefix`, as tf::resolve does: "prefix/frame" with the prefix's leading
/// '/' dropped; an empty prefix leaves the frame as it is; a frame that starts with '/'
/// is absolute (the '/' is dropped, no prefix added).
std::string resolveFrame(const std::string& prefix, const std::string& frame);

/// The tf_prefix parameter found from the robot's namespace upwards (searchParam), as
/// Gazebo's ROS plugins look it up; "" when there is none.
std::string findTfPrefix(const ros::NodeHandle& robot_nh);

}  // namespace bullet_sim_node
