// The simulation-control services: pause, unpause, resets, stepping, physics properties.
#pragma once

#include "runner/pacer.h"
#include "runner/sim_runner.h"

#include <bullet_sim/StepSimulation.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <gazebo_msgs/StepControl.h>
#include <ros/node_handle.h>
#include <std_srvs/Empty.h>

#include <functional>
#include <string>
#include <vector>

namespace bullet_sim_node {

/// pause_physics, unpause_physics, reset_simulation, reset_world, step_simulation,
/// step_control, get_physics_properties and set_physics_properties, advertised in
/// `gazebo_nh`.
/// The real-time factor is Gazebo's max_update_rate * time_step (0: as fast as possible).
class PhysicsServices {
 public:
  /// With `step_service`, also step_simulation (ours) and step_control (gazebo_ros_pkgs
  /// pull request 1280's): neither is in gazebo_ros's API.
  PhysicsServices(SimRunner& runner, Pacer& pacer, const ros::NodeHandle& gazebo_nh,
                  bool step_service);

  /// What get_physics_properties answers now.
  gazebo_msgs::GetPhysicsProperties::Response currentPhysics();
  /// Applies what set_physics_properties asks; "" or why it cannot be (nothing changed).
  /// Does not call the change callback.
  std::string applyPhysics(const gazebo_msgs::SetPhysicsProperties::Request& req);
  /// Called after set_physics_properties has changed the physics.
  void onChange(std::function<void()> callback) { on_change_ = std::move(callback); }

 private:
  bool pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool unpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool step(bullet_sim::StepSimulation::Request& req, bullet_sim::StepSimulation::Response& res);
  bool stepControl(gazebo_msgs::StepControl::Request& req,
                   gazebo_msgs::StepControl::Response& res);
  /// Takes exactly `steps` physics steps, publishing every sensor that falls due on the
  /// way stamped with its sim time, and returns once all of it is handed to roscpp.
  void advance(uint32_t steps);
  bool getPhysics(gazebo_msgs::GetPhysicsProperties::Request&,
                  gazebo_msgs::GetPhysicsProperties::Response& res);
  bool setPhysics(gazebo_msgs::SetPhysicsProperties::Request& req,
                  gazebo_msgs::SetPhysicsProperties::Response& res);

  SimRunner& runner_;
  Pacer& pacer_;
  std::vector<ros::ServiceServer> servers_;
  std::function<void()> on_change_;
};

/// Bullet's solver settings in ODE's fields, with the fields Bullet has no counterpart
/// for as they are reported (auto_disable_bodies true, max_contacts 4, the others 0).
gazebo_msgs::ODEPhysics odeConfig(const bullet_sim::SolverSettings& solver);

}  // namespace bullet_sim_node
