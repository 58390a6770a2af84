// gzserver's command line, translated for bullet_sim_node.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gazebo_ros_server {

/// A gzserver command line that cannot be run; the message says why.
class ServerArgsError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// gazebo_ros's launch files start `gzserver [-u] [-r] [--verbose] -e ode [extra] WORLD`
/// followed by ROS remappings. bullet_sim honours the world, `-u` (start paused) and
/// `--seed`; the other options of Gazebo 11 have no meaning for it and are reported once,
/// never an error.
struct ServerArgs {
  std::string world;                 ///< "" when none is given
  bool paused = false;
  std::optional<long long> seed;
  std::string physics = "ode";
  std::vector<std::string> ignored;  ///< options accepted without effect ("--record_path /r")
  std::vector<std::string> remappings;  ///< ROS arguments (name:=value), passed on
};

/// Throws ServerArgsError "gzserver option -e needs a value", or Python int()'s message
/// for a --seed that is not an integer.
ServerArgs parseServerArgs(const std::vector<std::string>& argv);

/// bullet_sim_node's private parameters for these arguments, then the remappings.
std::vector<std::string> nodeArguments(const ServerArgs& args, const std::string& world_path);

}  // namespace gazebo_ros_server
