// The link and joint services of gazebo_ros: link state and properties, joint
// properties, body wrenches and joint efforts.
#pragma once

#include "runner/sim_runner.h"

#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/LinkState.h>
#include <gazebo_msgs/SetLinkState.h>
#include <ros/node_handle.h>

#include <string>
#include <vector>

namespace bullet_sim_node {

/// get_link_state, set_link_state (service and topic), get_link_properties,
/// get_joint_properties, apply_body_wrench, apply_joint_effort, clear_body_wrenches and
/// clear_joint_forces, advertised in `gazebo_nh`. Links are named "model::link"; joints
/// "joint" or "model::joint". A request that cannot be honoured answers success false
/// with a message naming the value (clear_* have no answer fields: they fail the call).
class LinkJointServices {
 public:
  LinkJointServices(SimRunner& runner, const ros::NodeHandle& gazebo_nh);

 private:
  bool getLinkState(gazebo_msgs::GetLinkState::Request& req,
                    gazebo_msgs::GetLinkState::Response& res);
  bool setLinkState(gazebo_msgs::SetLinkState::Request& req,
                    gazebo_msgs::SetLinkState::Response& res);
  void onSetLinkState(const gazebo_msgs::LinkState::ConstPtr& state);
  bool getLinkProperties(gazebo_msgs::GetLinkProperties::Request& req,
                         gazebo_msgs::GetLinkProperties::Response& res);
  bool getJointProperties(gazebo_msgs::GetJointProperties::Request& req,
                          gazebo_msgs::GetJointProperties::Response& res);
  bool applyWrench(gazebo_msgs::ApplyBodyWrench::Request& req,
                   gazebo_msgs::ApplyBodyWrench::Response& res);
  bool applyEffort(gazebo_msgs::ApplyJointEffort::Request& req,
                   gazebo_msgs::ApplyJointEffort::Response& res);
  bool clearWrenches(gazebo_msgs::BodyRequest::Request& req,
                     gazebo_msgs::BodyRequest::Response&);
  bool clearEfforts(gazebo_msgs::JointRequest::Request& req,
                    gazebo_msgs::JointRequest::Response&);

  /// Applies a link state; returns "" or why it cannot be.
  std::string applyLinkState(const gazebo_msgs::LinkState& state);
  /// Queues a wrench; returns "" or why it cannot be.
  std::string queueWrench(const gazebo_msgs::ApplyBodyWrench::Request& req);

  SimRunner& runner_;
  std::vector<ros::ServiceServer> servers_;
  ros::Subscriber set_state_sub_;
};

}  // namespace bullet_sim_node
