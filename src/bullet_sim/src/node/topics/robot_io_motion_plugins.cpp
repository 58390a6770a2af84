// RobotIo: gazebo_plugins' libgazebo_ros_planar_move.so (Twist in; odometry and its tf
// out) and libgazebo_ros_joint_state_publisher.so (joint_states of its joints).
#include "topics/robot_io.h"

#include "topics/conversions.h"
#include "topics/tf_prefix.h"

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>

namespace bullet_sim_node {
namespace {

constexpr uint32_t kQueueSize = 200;  // as robot_io.cpp's
constexpr uint32_t kTfQueueSize = 100;

}  // namespace

void RobotIo::advertiseMotionPlugins(ros::NodeHandle& nh, const bullet_sim::RobotSpec& spec) {
  for (size_t i = 0; i < spec.joint_state_publishers.size(); ++i)
    plugin_joint_state_pubs_.push_back(
        CountedPublisher::advertise<sensor_msgs::JointState>(nh, "joint_states", kQueueSize));
  if (!spec.planar_move) return;
  const bullet_sim::PlanarMoveSpec& planar = *spec.planar_move;
  planar_odom_pub_ =
      CountedPublisher::advertise<nav_msgs::Odometry>(nh, planar.odometry_topic, kQueueSize);
  if (!tf_pub_) tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", kTfQueueSize);
  planar_cmd_sub_ = nh.subscribe(planar.command_topic, 1, &RobotIo::onPlanarMoveCommand, this,
                                 ros::TransportHints().tcpNoDelay());
}

void RobotIo::publishMotionPlugin(const bullet_sim::DueSensor& due) {
  if (due.kind == bullet_sim::SensorKind::PluginJointStates) {
    if (due.index < plugin_joint_state_pubs_.size() &&
        plugin_joint_state_pubs_[due.index].hasSubscribers()) {
      queue_.publish(plugin_joint_state_pubs_[due.index].publisher(),
                     toMsg(sim_.readPluginJointStates(robot_, due.index)));
    }
    return;
  }
  // As Gazebo's plugin: the odometry is read (its twist measured from the last reading)
  // and its tf sent at every period, subscribed or not.
  bullet_sim::OdometryData odom = sim_.readPlanarMoveOdometry(robot_);
  odom.frame_id = resolveFrame(tf_prefix_, odom.frame_id);
  odom.child_frame_id = resolveFrame(tf_prefix_, odom.child_frame_id);
  tf2_msgs::TFMessage tf;
  tf.transforms.push_back(toTransformMsg(odom));
  queue_.publish(tf_pub_, std::move(tf));
  if (!planar_odom_pub_.hasSubscribers()) return;
  nav_msgs::Odometry msg = toMsg(odom);
  msg.pose.pose.position.z = 0;  // Gazebo's message has no height; its tf has
  queue_.publish(planar_odom_pub_.publisher(), std::move(msg));
}

void RobotIo::onPlanarMoveCommand(const geometry_msgs::Twist::ConstPtr& command) {
  const double fields[3] = {command->linear.x, command->linear.y, command->angular.z};
  const char* names[3] = {"linear.x", "linear.y", "angular.z"};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(fields[i])) {
      ROS_WARN_THROTTLE(5.0, "robot %s: dropped a %s command: %s is %f", robot_.c_str(),
                        planar_cmd_sub_.getTopic().c_str(), names[i], fields[i]);
      return;
    }
  }
  sim_.setPlanarMoveCommand(robot_, fields[0], fields[1], fields[2]);
}

}  // namespace bullet_sim_node
