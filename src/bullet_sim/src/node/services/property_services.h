// gazebo_ros's services that change the world's lights and the properties of links and
// joints: delete_light, get_light_properties, set_light_properties, set_link_properties,
// set_joint_properties.
#pragma once

#include "runner/sim_runner.h"

#include <gazebo_msgs/DeleteLight.h>
#include <gazebo_msgs/GetLightProperties.h>
#include <gazebo_msgs/SetJointProperties.h>
#include <gazebo_msgs/SetLightProperties.h>
#include <gazebo_msgs/SetLinkProperties.h>
#include <ros/node_handle.h>

#include <vector>

namespace bullet_sim_node {

/// Advertised in `gazebo_nh`, called between steps like every service of the node, so a
/// light or a mass never changes while a step or a camera frame reads it. Lights are
/// Simulation::world().lights by name; links "model::link"; joints "joint" or
/// "model::joint". What cannot be honoured answers success false naming the field.
class PropertyServices {
 public:
  PropertyServices(SimRunner& runner, const ros::NodeHandle& gazebo_nh);

 private:
  bool deleteLight(gazebo_msgs::DeleteLight::Request& req,
                   gazebo_msgs::DeleteLight::Response& res);
  bool getLight(gazebo_msgs::GetLightProperties::Request& req,
                gazebo_msgs::GetLightProperties::Response& res);
  bool setLight(gazebo_msgs::SetLightProperties::Request& req,
                gazebo_msgs::SetLightProperties::Response& res);
  bool setLink(gazebo_msgs::SetLinkProperties::Request& req,
               gazebo_msgs::SetLinkProperties::Response& res);
  bool setJoint(gazebo_msgs::SetJointProperties::Request& req,
                gazebo_msgs::SetJointProperties::Response& res);

  SimRunner& runner_;
  std::vector<ros::ServiceServer> servers_;
};

}  // namespace bullet_sim_node
