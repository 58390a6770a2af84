#include "config.h"

#include <cmath>
#include <sstream>

namespace bullet_sim_node {
namespace {

void require(bool ok, const std::string& param, double value, const std::string& rule) {
  if (ok) return;
  std::ostringstream message;
  message << "parameter " << param << " = " << value << " is invalid: " << rule;
  throw ConfigError(message.str());
}

}  // namespace

Config readConfig(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh) {
  Config config;
  if (!private_nh.getParam("world_file", config.world_file) || config.world_file.empty())
    throw ConfigError("parameter " + private_nh.resolveName("world_file") +
                      " is not set: give the SDF world to load");
  private_nh.param("robot_name", config.robot_name, config.robot_name);
  if (!config.robot_name.empty() &&
      (!nh.getParam("robot_description", config.robot_description) ||
       config.robot_description.empty()))
    throw ConfigError("parameter " + nh.resolveName("robot_description") +
                      " is not set: load the URDF of robot '" + config.robot_name +
                      "' there (e.g. with xacro), or leave " +
                      private_nh.resolveName("robot_name") + " unset to start without a robot");
  private_nh.param("physics_step", config.physics_step_s, config.physics_step_s);
  private_nh.param("real_time_factor", config.real_time_factor, config.real_time_factor);
  private_nh.param("paused", config.start_paused, config.start_paused);
  private_nh.param("seed", config.seed, config.seed);
  private_nh.param("threads", config.threads, config.threads);
  private_nh.param("cmd_vel_timeout", config.cmd_vel_timeout_s, config.cmd_vel_timeout_s);
  private_nh.param("spawn_x", config.spawn_x_m, config.spawn_x_m);
  private_nh.param("spawn_y", config.spawn_y_m, config.spawn_y_m);
  private_nh.param("spawn_yaw", config.spawn_yaw_rad, config.spawn_yaw_rad);
  private_nh.param("status_period", config.status_period_s, config.status_period_s);
  private_nh.param("model_states_rate", config.model_states_rate_hz, config.model_states_rate_hz);
  private_nh.param("enable_ros_network", config.enable_ros_network, config.enable_ros_network);
  private_nh.param("step_simulation_service", config.step_service, config.step_service);
  private_nh.param("spawn_model_service", config.spawn_model_service, config.spawn_model_service);
  config.markers_param = private_nh.resolveName("markers");

  require(std::isfinite(config.physics_step_s) && config.physics_step_s >= 0 &&
              config.physics_step_s <= 0.1,
          "~physics_step", config.physics_step_s, "must be in [0, 0.1] s (0 = the world's)");
  require(std::isfinite(config.real_time_factor) && config.real_time_factor >= 0,
          "~real_time_factor", config.real_time_factor, "must be >= 0 (0 = as fast as possible)");
  require(config.seed >= 0, "~seed", config.seed, "must be >= 0");
  require(config.threads >= 0 && config.threads <= 256, "~threads", config.threads,
          "must be in [0, 256] (0 = the machine's hardware threads)");
  require(std::isfinite(config.cmd_vel_timeout_s) && config.cmd_vel_timeout_s >= 0,
          "~cmd_vel_timeout", config.cmd_vel_timeout_s, "must be >= 0 s (0 = never)");
  require(std::isfinite(config.spawn_x_m), "~spawn_x", config.spawn_x_m, "must be finite");
  require(std::isfinite(config.spawn_y_m), "~spawn_y", config.spawn_y_m, "must be finite");
  require(std::isfinite(config.spawn_yaw_rad), "~spawn_yaw", config.spawn_yaw_rad,
          "must be finite");
  require(std::isfinite(config.status_period_s) && config.status_period_s > 0,
          "~status_period", config.status_period_s, "must be > 0 s");
  require(std::isfinite(config.model_states_rate_hz) && config.model_states_rate_hz > 0,
          "~model_states_rate", config.model_states_rate_hz, "must be > 0 Hz");
  return config;
}

std::string commandLineWorldFile(int argc, const char* const* argv) {
  const std::string prefix = "_world_file:=";
  std::string world;
  for (int i = 1; i < argc; ++i) {  // the last one counts, as for roscpp's parameters
    const std::string arg = argv[i];
    if (arg.compare(0, prefix.size(), prefix) == 0) world = arg.substr(prefix.size());
  }
  return world;
}

}  // namespace bullet_sim_node
