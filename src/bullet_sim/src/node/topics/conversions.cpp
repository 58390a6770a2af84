#include "topics/conversions.h"

#include <algorithm>
#include <cmath>

namespace bullet_sim_node {
namespace {

geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q) {
  geometry_msgs::Quaternion msg;
  msg.w = q.w();
  msg.x = q.x();
  msg.y = q.y();
  msg.z = q.z();
  return msg;
}

void setDiagonal(boost::array<double, 9>& covariance, double variance) {
  covariance.fill(0.0);
  covariance[0] = covariance[4] = covariance[8] = variance;
}

}  // namespace

std_msgs::Header toHeader(double time_s, const std::string& frame_id) {
  std_msgs::Header header;
  header.stamp.fromSec(time_s);
  header.frame_id = frame_id;
  return header;
}

geometry_msgs::Vector3 toMsg(const Eigen::Vector3d& vector) {
  geometry_msgs::Vector3 msg;
  msg.x = vector.x();
  msg.y = vector.y();
  msg.z = vector.z();
  return msg;
}

geometry_msgs::Pose toMsg(const bullet_sim::Pose3& pose) {
  geometry_msgs::Pose msg;
  msg.position.x = pose.position.x();
  msg.position.y = pose.position.y();
  msg.position.z = pose.position.z();
  msg.orientation = toQuaternion(pose.orientation);
  return msg;
}

geometry_msgs::Twist toMsg(const bullet_sim::Twist3& twist) {
  geometry_msgs::Twist msg;
  msg.linear = toMsg(twist.linear);
  msg.angular = toMsg(twist.angular);
  return msg;
}

bullet_sim::Pose3 fromMsg(const geometry_msgs::Pose& pose) {
  bullet_sim::Pose3 result;
  result.position = {pose.position.x, pose.position.y, pose.position.z};
  const Eigen::Quaterniond q(pose.orientation.w, pose.orientation.x, pose.orientation.y,
                             pose.orientation.z);
  result.orientation = q.norm() > 1e-9 ? q.normalized() : Eigen::Quaterniond::Identity();
  return result;
}

bullet_sim::Twist3 fromMsg(const geometry_msgs::Twist& twist) {
  bullet_sim::Twist3 result;
  result.linear = {twist.linear.x, twist.linear.y, twist.linear.z};
  result.angular = {twist.angular.x, twist.angular.y, twist.angular.z};
  return result;
}

sensor_msgs::LaserScan toMsg(const bullet_sim::LaserScanData& scan) {
  sensor_msgs::LaserScan msg;
  msg.header = toHeader(scan.time_s, scan.frame_id);
  msg.angle_min = scan.angle_min;
  msg.angle_max = scan.angle_max;
  msg.angle_increment = scan.angle_increment;
  msg.time_increment = scan.time_increment;
  msg.scan_time = scan.scan_time;
  msg.range_min = scan.range_min;
  msg.range_max = scan.range_max;
  msg.ranges = scan.ranges;
  msg.intensities = scan.intensities;
  return msg;
}

sensor_msgs::Imu toMsg(const bullet_sim::ImuData& imu) {
  sensor_msgs::Imu msg;
  msg.header = toHeader(imu.time_s, imu.frame_id);
  msg.orientation = toQuaternion(imu.orientation);
  msg.angular_velocity = toMsg(imu.angular_velocity);
  msg.linear_acceleration = toMsg(imu.linear_acceleration);
  setDiagonal(msg.orientation_covariance, imu.orientation_cov);
  setDiagonal(msg.angular_velocity_covariance, imu.angular_velocity_cov);
  setDiagonal(msg.linear_acceleration_covariance, imu.linear_acceleration_cov);
  return msg;
}

geometry_msgs::WrenchStamped toMsg(const bullet_sim::WrenchData& wrench) {
  geometry_msgs::WrenchStamped msg;
  msg.header.stamp.fromSec(wrench.time_s);
  msg.header.frame_id = wrench.frame_id;
  msg.wrench.force.x = wrench.force_n.x();
  msg.wrench.force.y = wrench.force_n.y();
  msg.wrench.force.z = wrench.force_n.z();
  msg.wrench.torque.x = wrench.torque_nm.x();
  msg.wrench.torque.y = wrench.torque_nm.y();
  msg.wrench.torque.z = wrench.torque_nm.z();
  return msg;
}

nav_msgs::Odometry toMsg(const bullet_sim::OdometryData& odom) {
  nav_msgs::Odometry msg;
  msg.header = toHeader(odom.time_s, odom.frame_id);
  msg.child_frame_id = odom.child_frame_id;
  msg.pose.pose = toMsg(odom.pose);
  msg.twist.twist = toMsg(odom.twist_in_child);
  std::copy(odom.pose_covariance.begin(), odom.pose_covariance.end(), msg.pose.covariance.begin());
  std::copy(odom.twist_covariance.begin(), odom.twist_covariance.end(),
            msg.twist.covariance.begin());
  return msg;
}

sensor_msgs::JointState toMsg(const bullet_sim::JointStateData& joints) {
  sensor_msgs::JointState msg;
  msg.header.stamp.fromSec(joints.time_s);
  msg.name = joints.names;
  msg.position = joints.positions;
  msg.velocity = joints.velocities;
  msg.effort = joints.efforts;
  return msg;
}

geometry_msgs::TransformStamped toTransformMsg(const bullet_sim::OdometryData& odom) {
  geometry_msgs::TransformStamped msg;
  msg.header = toHeader(odom.time_s, odom.frame_id);
  msg.child_frame_id = odom.child_frame_id;
  msg.transform.translation.x = odom.pose.position.x();
  msg.transform.translation.y = odom.pose.position.y();
  msg.transform.translation.z = odom.pose.position.z();
  msg.transform.rotation = toQuaternion(odom.pose.orientation);
  return msg;
}

Eigen::Vector3d fromMsg(const geometry_msgs::Vector3& vector) {
  return Eigen::Vector3d(vector.x, vector.y, vector.z);
}

std::optional<std::string> firstNonFinite(const geometry_msgs::Vector3& vector,
                                          const std::string& name) {
  const std::pair<const char*, double> fields[] = {{"x", vector.x}, {"y", vector.y}, {"z", vector.z}};
  for (const auto& field : fields) {
    if (!std::isfinite(field.second)) {
      return name + "." + field.first + " = " + std::to_string(field.second);
    }
  }
  return std::nullopt;
}

std::optional<std::string> firstNonFinite(const geometry_msgs::Pose& pose) {
  geometry_msgs::Vector3 position;
  position.x = pose.position.x;
  position.y = pose.position.y;
  position.z = pose.position.z;
  if (auto bad = firstNonFinite(position, "position")) return bad;
  const std::pair<const char*, double> fields[] = {
      {"x", pose.orientation.x}, {"y", pose.orientation.y}, {"z", pose.orientation.z},
      {"w", pose.orientation.w}};
  for (const auto& field : fields) {
    if (!std::isfinite(field.second)) {
      return std::string("orientation.") + field.first + " = " + std::to_string(field.second);
    }
  }
  return std::nullopt;
}

std::optional<std::string> firstNonFinite(const geometry_msgs::Twist& twist) {
  if (auto bad = firstNonFinite(twist.linear, "linear")) return bad;
  return firstNonFinite(twist.angular, "angular");
}

}  // namespace bullet_sim_node
