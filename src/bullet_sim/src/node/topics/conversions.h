// Adapts the core's ROS-free data types to ROS messages (and back for poses).
#pragma once

#include <bullet_sim/sensors/sensor_data.h>
#include <bullet_sim/types.h>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Header.h>

#include <optional>
#include <string>

namespace bullet_sim_node {

/// The header of a reading taken at sim time `time_s` in frame `frame_id`.
std_msgs::Header toHeader(double time_s, const std::string& frame_id);
geometry_msgs::Vector3 toMsg(const Eigen::Vector3d& vector);
geometry_msgs::Pose toMsg(const bullet_sim::Pose3& pose);
geometry_msgs::Twist toMsg(const bullet_sim::Twist3& twist);
/// Normalises the quaternion; a zero quaternion (an unset message) becomes the identity.
bullet_sim::Pose3 fromMsg(const geometry_msgs::Pose& pose);
bullet_sim::Twist3 fromMsg(const geometry_msgs::Twist& twist);
Eigen::Vector3d fromMsg(const geometry_msgs::Vector3& vector);

sensor_msgs::LaserScan toMsg(const bullet_sim::LaserScanData& scan);
sensor_msgs::Imu toMsg(const bullet_sim::ImuData& imu);
nav_msgs::Odometry toMsg(const bullet_sim::OdometryData& odom);
sensor_msgs::JointState toMsg(const bullet_sim::JointStateData& joints);
geometry_msgs::WrenchStamped toMsg(const bullet_sim::WrenchData& wrench);
/// The odom -> base transform carried by an odometry reading.
geometry_msgs::TransformStamped toTransformMsg(const bullet_sim::OdometryData& odom);

/// "position.x = nan"-style description of the first non-finite field, if any.
std::optional<std::string> firstNonFinite(const geometry_msgs::Pose& pose);
std::optional<std::string> firstNonFinite(const geometry_msgs::Twist& twist);
std::optional<std::string> firstNonFinite(const geometry_msgs::Vector3& vector,
                                          const std::string& name);

}  // namespace bullet_sim_node
