// The model services of gazebo_ros: spawn, delete, model state, world and model properties.
#pragma once

#include "runner/sim_runner.h"

#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/ModelState.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SpawnModel.h>
#include <ros/node_handle.h>

#include <string>
#include <vector>

namespace bullet_sim_node {

/// spawn_urdf_model (also as spawn_model), spawn_sdf_model, delete_model,
/// get_model_state, set_model_state (service and topic), get_world_properties,
/// get_model_properties and set_model_configuration, advertised in `gazebo_nh`.
/// A request that cannot be honoured answers success false with a message naming the
/// value; reference frames are "" / "world", a model or "model::link".
class ModelServices {
 public:
  /// With `spawn_model_service`, also spawn_model (ours: not in gazebo_ros's API).
  ModelServices(SimRunner& runner, const ros::NodeHandle& gazebo_nh, bool spawn_model_service);

 private:
  bool spawn(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res);
  bool remove(gazebo_msgs::DeleteModel::Request& req, gazebo_msgs::DeleteModel::Response& res);
  bool getState(gazebo_msgs::GetModelState::Request& req,
                gazebo_msgs::GetModelState::Response& res);
  bool setState(gazebo_msgs::SetModelState::Request& req,
                gazebo_msgs::SetModelState::Response& res);
  void onSetState(const gazebo_msgs::ModelState::ConstPtr& state);
  bool getWorld(gazebo_msgs::GetWorldProperties::Request&,
                gazebo_msgs::GetWorldProperties::Response& res);
  bool getProperties(gazebo_msgs::GetModelProperties::Request& req,
                     gazebo_msgs::GetModelProperties::Response& res);
  bool setConfiguration(gazebo_msgs::SetModelConfiguration::Request& req,
                        gazebo_msgs::SetModelConfiguration::Response& res);

  /// Applies a model state; returns "" or why it cannot be.
  std::string applyState(const gazebo_msgs::ModelState& state);
  /// Parses and spawns; returns "" or why it cannot be.
  std::string spawnModel(const gazebo_msgs::SpawnModel::Request& req);
  bool hasModel(const std::string& name) const;

  SimRunner& runner_;
  std::vector<ros::ServiceServer> servers_;
  ros::Subscriber set_state_sub_;
};

}  // namespace bullet_sim_node
