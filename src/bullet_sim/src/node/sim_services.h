// The simulator's services, named as gazebo_ros names them (/gazebo/...).
#pragma once

#include "sim_runner.h"

#include <bullet_sim/DeleteModel.h>
#include <bullet_sim/GetModelState.h>
#include <bullet_sim/SetModelState.h>
#include <bullet_sim/SpawnModel.h>
#include <bullet_sim/StepSimulation.h>
#include <ros/node_handle.h>
#include <std_srvs/Empty.h>

#include <vector>

namespace bullet_sim_node {

/// pause_physics, unpause_physics, reset_simulation, reset_world, step_simulation,
/// spawn_urdf_model (also as spawn_model), delete_model, get_model_state and
/// set_model_state, advertised in `nh` (the launch uses /gazebo so Gazebo scripts work).
class SimServices {
 public:
  SimServices(SimRunner& runner, const ros::NodeHandle& nh);

 private:
  bool pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool unpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool step(bullet_sim::StepSimulation::Request& req, bullet_sim::StepSimulation::Response& res);
  bool spawn(bullet_sim::SpawnModel::Request& req, bullet_sim::SpawnModel::Response& res);
  bool remove(bullet_sim::DeleteModel::Request& req, bullet_sim::DeleteModel::Response& res);
  bool getState(bullet_sim::GetModelState::Request& req,
                bullet_sim::GetModelState::Response& res);
  bool setState(bullet_sim::SetModelState::Request& req,
                bullet_sim::SetModelState::Response& res);
  bool hasRobot(const std::string& name) const;

  SimRunner& runner_;
  std::vector<ros::ServiceServer> servers_;
};

}  // namespace bullet_sim_node
