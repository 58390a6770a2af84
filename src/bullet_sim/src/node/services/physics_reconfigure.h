// gazebo_ros's dynamic_reconfigure server of the physics on /gazebo (set_parameters,
// parameter_descriptions, parameter_updates).
#pragma once

#include "services/physics_services.h"

#include <bullet_sim/PhysicsConfig.h>
#include <dynamic_reconfigure/server.h>
#include <ros/node_handle.h>

#include <boost/thread/recursive_mutex.hpp>

namespace bullet_sim_node {

/// The physics as dynamic_reconfigure parameters with gazebo_ros's names (cfg/Physics.cfg),
/// kept equal to what get_physics_properties answers: filled from it at start, a change
/// goes through the same code as set_physics_properties, and what the simulation then has
/// is published back (a value it cannot take snaps back, with a warning naming it). Its
/// service is called between steps like every other.
class PhysicsReconfigure {
 public:
  PhysicsReconfigure(PhysicsServices& physics, const ros::NodeHandle& gazebo_nh);
  PhysicsReconfigure(const PhysicsReconfigure&) = delete;
  PhysicsReconfigure& operator=(const PhysicsReconfigure&) = delete;

  /// Publishes the physics as they are now (after a set_physics_properties call).
  void publishCurrent();

 private:
  void onReconfigure(bullet_sim::PhysicsConfig& config, uint32_t level);

  PhysicsServices& physics_;
  boost::recursive_mutex mutex_;
  dynamic_reconfigure::Server<bullet_sim::PhysicsConfig> server_;
  bool initialized_ = false;
};

}  // namespace bullet_sim_node
