// rosrun gazebo_ros spawn_model: adds a URDF or SDF model to the simulation, with
// Gazebo's command line (spawn_args.h) and exit codes: 0 spawned, 1 a wrong argument
// (with the usage), a model that cannot be read, or one the simulator refused.
#include "gazebo_client.h"
#include "model_text.h"
#include "rpy.h"
#include "spawn_args.h"

#include <ros/ros.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace gazebo_ros_spawn;

std::atomic<bool> g_stop{false};

void requestStop(int) { g_stop = true; }

std::string nodeName(const std::string& model) {
  std::string name = "spawn_" + model;
  for (char& c : name) {
    if (c == ':') c = '_';
  }
  return name;
}

/// The model text from -file, -param or stdin, checked to be XML.
std::string readModel(const SpawnArgs& args) {
  std::string text, source;
  if (args.has_file) {
    text = readModelFile(args.file);
    source = "file " + args.file;
  } else if (args.has_param) {
    source = "parameter " + args.param;
    if (!ros::NodeHandle().getParam(args.param, text) || text.empty()) {
      throw ModelError("parameter " + ros::names::resolve(args.param) +
                       " does not exist or is empty");
    }
  } else {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    source = "stdin";
  }
  checkXml(text, source);
  return args.package_to_model ? packageToModel(text) : text;
}

gazebo_msgs::SpawnModel::Request spawnRequest(const SpawnArgs& args, std::string model_xml) {
  gazebo_msgs::SpawnModel::Request request;
  request.model_name = args.model;
  request.model_xml = std::move(model_xml);
  request.robot_namespace = args.robot_namespace;
  request.reference_frame = args.reference_frame;
  request.initial_pose.position.x = args.x;
  request.initial_pose.position.y = args.y;
  request.initial_pose.position.z = args.z;
  const Quaternion q = quaternionFromRpy(args.R, args.P, args.Y);
  request.initial_pose.orientation.x = q.x;
  request.initial_pose.orientation.y = q.y;
  request.initial_pose.orientation.z = q.z;
  request.initial_pose.orientation.w = q.w;
  return request;
}

/// -b: waits for SIGINT or SIGTERM (roslaunch's stop), then deletes the model.
int holdUntilStopped(const SpawnArgs& args) {
  ROS_INFO("Waiting for shutdown to delete model %s", args.model.c_str());
  while (!g_stop && ros::ok()) ros::WallDuration(0.05).sleep();
  deleteModel(args.gazebo_namespace, args.model);
  return 0;
}

int run(SpawnArgs args) {
  ros::NodeHandle node;  // starts the node: the master calls below need it
  if (!args.has_robot_namespace) {
    const std::string ns = ros::this_node::getNamespace();
    args.robot_namespace = ns.back() == '/' ? ns : ns + "/";
  }
  if (!args.wait.empty() && !waitForModel(args.gazebo_namespace, args.wait)) return 1;
  std::string model_xml;
  try {
    model_xml = readModel(args);
  } catch (const ModelError& error) {
    ROS_ERROR("Error: %s", error.what());
    return 1;
  }
  if (!spawnModel(args.gazebo_namespace, args.urdf, spawnRequest(args, std::move(model_xml)))) {
    ROS_ERROR("Spawn service failed. Exiting.");
    return 1;
  }
  if (!args.joints.empty() &&
      !setModelConfiguration(args.gazebo_namespace, args.model, args.param, args.joints)) {
    ROS_ERROR("SetModelConfiguration service failed. Exiting.");
    return 1;
  }
  if (args.unpause && !unpausePhysics(args.gazebo_namespace)) return 1;
  return args.bond ? holdUntilStopped(args) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  SpawnArgs args;
  try {
    args = parseSpawnArgs(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const HelpRequested&) {
    std::cout << help();
    return 0;
  } catch (const UsageError& error) {
    std::cerr << error.what() << std::endl;
    return 1;
  }
  try {
    ros::init(argc, argv, nodeName(args.model),
              ros::init_options::AnonymousName |
                  (args.bond ? ros::init_options::NoSigintHandler : 0));
  } catch (const ros::InvalidNameException& error) {
    std::cerr << "spawn_model: -model " << args.model << ": " << error.what() << std::endl;
    return 1;
  }
  if (args.bond) {
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
  }
  const int status = run(args);
  ros::shutdown();
  return status;
}
