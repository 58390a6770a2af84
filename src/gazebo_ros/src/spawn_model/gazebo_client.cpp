#include "gazebo_client.h"

#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>

#include <algorithm>

namespace gazebo_ros_spawn {
namespace {

/// Waits for the service, calls it and logs the answer's status message (an error when
/// it did not succeed). False when the call failed or the simulator refused.
template <class Service>
bool callLogged(const std::string& name, Service* service) {
  ROS_INFO("Waiting for service %s", name.c_str());
  if (!waitForService(name)) return false;
  if (!ros::service::call(name, *service)) {
    ROS_ERROR("%s call failed: no answer from the service", name.c_str());
    return false;
  }
  if (service->response.success) {
    ROS_INFO("%s: %s", name.c_str(), service->response.status_message.c_str());
  } else {
    ROS_ERROR("%s: %s", name.c_str(), service->response.status_message.c_str());
  }
  return service->response.success;
}

}  // namespace

bool waitForService(const std::string& service) {
  while (ros::ok()) {
    if (ros::service::exists(service, false)) return true;
    ros::WallDuration(0.01).sleep();
  }
  return false;
}

bool waitForModel(const std::string& gazebo_namespace, const std::string& model) {
  const std::string service = gazebo_namespace + "/get_world_properties";
  ROS_INFO("Waiting for model %s before proceeding.", model.c_str());
  if (!waitForService(service)) return false;
  while (ros::ok()) {
    gazebo_msgs::GetWorldProperties world;
    if (ros::service::call(service, world)) {
      const std::vector<std::string>& names = world.response.model_names;
      if (std::find(names.begin(), names.end(), model) != names.end()) return true;
    }
    ros::WallDuration(0.1).sleep();
  }
  return false;
}

bool spawnModel(const std::string& gazebo_namespace, bool urdf,
                gazebo_msgs::SpawnModel::Request request) {
  gazebo_msgs::SpawnModel spawn;
  spawn.request = std::move(request);
  return callLogged(gazebo_namespace + (urdf ? "/spawn_urdf_model" : "/spawn_sdf_model"),
                    &spawn);
}

bool setModelConfiguration(const std::string& gazebo_namespace, const std::string& model,
                           const std::string& urdf_param,
                           const std::vector<std::pair<std::string, double>>& joints) {
  gazebo_msgs::SetModelConfiguration configuration;
  configuration.request.model_name = model;
  configuration.request.urdf_param_name = urdf_param;
  for (const auto& joint : joints) {
    configuration.request.joint_names.push_back(joint.first);
    configuration.request.joint_positions.push_back(joint.second);
  }
  return callLogged(gazebo_namespace + "/set_model_configuration", &configuration);
}

bool unpausePhysics(const std::string& gazebo_namespace) {
  const std::string service = gazebo_namespace + "/unpause_physics";
  std_srvs::Empty empty;
  if (!waitForService(service)) return false;
  if (ros::service::call(service, empty)) return true;
  ROS_ERROR("%s call failed: no answer from the service", service.c_str());
  return false;
}

bool deleteModel(const std::string& gazebo_namespace, const std::string& model) {
  gazebo_msgs::DeleteModel remove;
  remove.request.model_name = model;
  return callLogged(gazebo_namespace + "/delete_model", &remove);
}

}  // namespace gazebo_ros_spawn
