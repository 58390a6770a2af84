// Calls of the simulator's /gazebo services, logged as gazebo_ros's Python
// gazebo_interface logs them.
#pragma once

#include <gazebo_msgs/SpawnModel.h>

#include <string>
#include <utility>
#include <vector>

namespace gazebo_ros_spawn {

/// Returns true once the master knows `service` (looked up every 10 ms: the simulator's
/// services come up while a launch starts), false if the node is shut down first.
bool waitForService(const std::string& service);

/// Waits until the world has a model named `model` (asked every 0.1 s).
bool waitForModel(const std::string& gazebo_namespace, const std::string& model);

/// /spawn_urdf_model (urdf true) or /spawn_sdf_model of `gazebo_namespace`; logs the
/// simulator's answer. True when the model was spawned.
bool spawnModel(const std::string& gazebo_namespace, bool urdf,
                gazebo_msgs::SpawnModel::Request request);

/// /set_model_configuration: joint positions of a spawned model.
bool setModelConfiguration(const std::string& gazebo_namespace, const std::string& model,
                           const std::string& urdf_param,
                           const std::vector<std::pair<std::string, double>>& joints);

/// /unpause_physics.
bool unpausePhysics(const std::string& gazebo_namespace);

/// /delete_model.
bool deleteModel(const std::string& gazebo_namespace, const std::string& model);

}  // namespace gazebo_ros_spawn
