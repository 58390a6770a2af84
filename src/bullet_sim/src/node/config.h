// Parameters of bullet_sim_node, read once at start and validated.
#pragma once

#include <ros/node_handle.h>

#include <stdexcept>
#include <string>

namespace bullet_sim_node {

/// A parameter with a value the node cannot run with; the message names it.
class ConfigError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Config {
  std::string world_file;            ///< ~world_file: SDF world (required)
  double physics_step_s = 0;         ///< ~physics_step: 0 = the world's max_step_size
  double real_time_factor = 1;       ///< ~real_time_factor: 1 real time, k faster, 0 unpaced
  bool start_paused = false;         ///< ~paused
  int seed = 1;                      ///< ~seed of every sensor noise source
  int threads = 0;                   ///< ~threads stepping the physics; 0 = hardware threads
  double cmd_vel_timeout_s = 0;      ///< ~cmd_vel_timeout: stop a robot whose commands stop
                                     ///< for this long (sim s); 0 = never, as Gazebo
  double spawn_x_m = 0, spawn_y_m = 0, spawn_yaw_rad = 0;  ///< ~spawn_x, ~spawn_y, ~spawn_yaw
  /// ~robot_name: when set, robot_description is spawned at start under this name;
  /// when empty the world starts without robots (they come through the spawn services).
  std::string robot_name;
  double status_period_s = 1;        ///< ~status_period: wall seconds between status lines
  double model_states_rate_hz = 100; ///< ~model_states_rate: /gazebo/model_states, link_states
  std::string robot_description;     ///< the URDF (robot_description), read when robot_name is set
  /// ~enable_ros_network (gazebo_ros's): false leaves /clock and the robots' own topics
  /// only, no /gazebo service or topic
  bool enable_ros_network = true;
  bool step_service = false;         ///< ~step_simulation_service: /gazebo/step_simulation
  bool spawn_model_service = false;  ///< ~spawn_model_service: /gazebo/spawn_model
  /// The full name of ~markers, read while running: /gazebo/world_markers and
  /// model_markers are offered while it is true (gzclient sets it while it runs).
  std::string markers_param;
};

/// Reads the private parameters from `private_nh` and, when ~robot_name is set,
/// robot_description from `nh`.
/// Throws ConfigError naming the parameter and its value when one is missing or out of range.
Config readConfig(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);

/// The world file given on the command line `argv` as a private parameter
/// (`_world_file:=PATH`, as gzserver starts the node), known before ros::init; "" when it is
/// not there (the parameter server may still hold ~world_file). roscpp turns such arguments
/// into parameters and keeps them out of its remappings, so they are read here.
std::string commandLineWorldFile(int argc, const char* const* argv);

}  // namespace bullet_sim_node
