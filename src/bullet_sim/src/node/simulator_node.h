// The whole simulator as bullet_sim_node and the bullet_sim/Simulator nodelet run it.
#pragma once

#include "config.h"
#include "runner/pacer.h"
#include "runner/sim_runner.h"
#include "runner/status_reporter.h"
#include "services/link_joint_services.h"
#include "services/model_services.h"
#include "services/physics_reconfigure.h"
#include "services/physics_services.h"
#include "services/property_services.h"
#include "topics/world_markers_io.h"

#include <bullet_sim/description/world_spec.h>
#include <bullet_sim/simulation.h>

#include <ros/callback_queue.h>
#include <ros/node_handle.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace bullet_sim_node {

/// The world's simulation with its topics, tf and /gazebo services. Every subscriber and
/// service lives on the callback queue of the NodeHandles it is given (`nh` for the
/// robots' topics, `gazebo_nh` for /gazebo), and only spinOnce() calls them, between
/// steps, so a service never sees a half-made step.
class SimulatorNode {
 public:
  /// Loads the world, spawns robot_description when ~robot_name is set and advertises
  /// everything. Throws bullet_sim::LoadError (the world or robot) naming the file,
  /// element and value.
  SimulatorNode(const Config& config, const ros::NodeHandle& nh, const ros::NodeHandle& gazebo_nh);
  /// The same with the world of config.world_file already loaded.
  SimulatorNode(const Config& config, const bullet_sim::WorldSpec& world,
                const ros::NodeHandle& nh, const ros::NodeHandle& gazebo_nh);
  SimulatorNode(const SimulatorNode&) = delete;
  SimulatorNode& operator=(const SimulatorNode&) = delete;

  /// One turn of the loop: runs the waiting callbacks of `callbacks`, then (unless
  /// paused) steps once and waits for the wall clock at the real-time factor. Paused, it
  /// waits up to 10 ms for a callback instead and keeps /clock published.
  void spinOnce(ros::CallbackQueue& callbacks);

 private:
  /// Offers or withdraws the marker topics as ~markers says (checked a few times a second).
  void updateMarkers();

  std::unique_ptr<bullet_sim::Simulation> sim_;
  std::unique_ptr<SimRunner> runner_;
  Pacer pacer_;
  std::unique_ptr<PhysicsServices> physics_services_;
  std::unique_ptr<ModelServices> model_services_;
  std::unique_ptr<LinkJointServices> link_joint_services_;
  std::unique_ptr<PropertyServices> property_services_;
  std::unique_ptr<StatusReporter> status_;
  std::unique_ptr<PhysicsReconfigure> physics_reconfigure_;
  std::unique_ptr<WorldMarkersIo> world_markers_;  ///< null while ~markers is not true
  ros::NodeHandle gazebo_nh_;
  std::string markers_param_;
  std::vector<std::string> world_models_;  ///< the world's movable models, drawn with it
  std::chrono::steady_clock::time_point last_markers_check_;
};

}  // namespace bullet_sim_node
