// spawn_model's command line, as Gazebo's (argparse) reads it.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gazebo_ros_spawn {

/// A command line spawn_model cannot run with; what() is the whole text to print
/// (argparse's usage and error line for a malformed one).
class UsageError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// -h / --help was given: print help() and exit 0.
struct HelpRequested {};

struct SpawnArgs {
  bool urdf = false, sdf = false;
  std::string file, param, database;
  bool has_file = false, has_param = false, has_database = false, from_stdin = false;
  std::string model;
  std::string reference_frame;
  std::string gazebo_namespace = "/gazebo";
  std::string robot_namespace;
  bool has_robot_namespace = false;  ///< false: the node's namespace (known after ros::init)
  bool unpause = false;
  std::string wait;
  double x = 0, y = 0, z = 0, R = 0, P = 0, Y = 0;
  std::vector<std::pair<std::string, double>> joints;  ///< -J JOINT POSITION, in order
  bool package_to_model = false;
  bool bond = false;  ///< -b
};

/// Parses spawn_model's arguments (words with ':=', ROS remappings, are left out) with the
/// rules and messages of Python's argparse, as the Python spawn_model did: unique prefixes
/// of an option are accepted ("-mod"), "-x=1" and "-x1" give a value, "-1.5" is a value.
/// Throws UsageError (usage and "spawn_model: error: ...") or HelpRequested.
SpawnArgs parseSpawnArgs(const std::vector<std::string>& argv);

/// argparse's usage text ("usage: spawn_model [-h] ..."), ending with a newline.
const std::string& usage();
/// The text of --help.
const std::string& help();

}  // namespace gazebo_ros_spawn
