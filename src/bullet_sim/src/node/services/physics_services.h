// The simulation-control services: pause, unpause, resets, stepping, physics properties.
#pragma once

#include "runner/pacer.h"
#include "runner/sim_runner.h"

#include <bullet_sim/StepSimulation.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <ros/node_handle.h>
#include <std_srvs/Empty.h>

#include <vector>

namespace bullet_sim_node {

/// pause_physics, unpause_physics, reset_simulation, reset_world, step_simulation,
/// get_physics_properties and set_physics_properties, advertised in `gazebo_nh`.
/// The real-time factor is Gazebo's max_update_rate * time_step (0: as fast as possible).
class PhysicsServices {
 public:
  PhysicsServices(SimRunner& runner, Pacer& pacer, const ros::NodeHandle& gazebo_nh);

 private:
  bool pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool unpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool step(bullet_sim::StepSimulation::Request& req, bullet_sim::StepSimulation::Response& res);
  bool getPhysics(gazebo_msgs::GetPhysicsProperties::Request&,
                  gazebo_msgs::GetPhysicsProperties::Response& res);
  bool setPhysics(gazebo_msgs::SetPhysicsProperties::Request& req,
                  gazebo_msgs::SetPhysicsProperties::Response& res);

  SimRunner& runner_;
  Pacer& pacer_;
  std::vector<ros::ServiceServer> servers_;
};

}  // namespace bullet_sim_node
