// bullet_sim_node: runs the Bullet simulation of a world, publishing /clock and the
// robots' sensors and offering gazebo_ros's services and topics under /gazebo. A robot
// is spawned from robot_description at start only when ~robot_name is set; others arrive
// through /gazebo/spawn_urdf_model. The bullet_sim/Simulator nodelet runs the same.
#include "config.h"
#include "gazebo_paths.h"
#include "simulator_node.h"

#include <bullet_sim/description/world_spec.h>
#include <bullet_sim/errors.h>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <future>
#include <memory>
#include <string>

namespace {

using bullet_sim_node::Config;
using bullet_sim_node::SimulatorNode;

/// Starts loading the world file named on the command line on a thread of its own, so
/// that libsdformat parses it while roscpp starts (its XML-RPC server, /rosout, the
/// parameters); no future when the command line names none.
std::future<bullet_sim::WorldSpec> preloadWorld(const std::string& world_file) {
  if (world_file.empty()) return {};
  return std::async(std::launch::async,
                    [world_file] { return bullet_sim::loadWorldFile(world_file); });
}

/// The simulator, with the world preloaded from `preloaded_file` when it is the one
/// ~world_file names.
std::unique_ptr<SimulatorNode> startSimulator(const Config& config,
                                              const std::string& preloaded_file,
                                              std::future<bullet_sim::WorldSpec>* preloaded,
                                              const ros::NodeHandle& nh,
                                              const ros::NodeHandle& gazebo_nh) {
  if (preloaded->valid() && config.world_file == preloaded_file) {
    return std::make_unique<SimulatorNode>(config, preloaded->get(), nh, gazebo_nh);
  }
  return std::make_unique<SimulatorNode>(config, nh, gazebo_nh);
}

}  // namespace

int main(int argc, char** argv) {
  bullet_sim_node::collectExportedModelPaths();
  const std::string world_file = bullet_sim_node::commandLineWorldFile(argc, argv);
  std::future<bullet_sim::WorldSpec> world = preloadWorld(world_file);
  ros::init(argc, argv, "bullet_sim");
  ros::NodeHandle nh;  // outlives the messages below: its end shuts roscpp's console down
  try {
    const Config config = bullet_sim_node::readConfig(nh, ros::NodeHandle("~"));
    const ros::NodeHandle gazebo_nh("/gazebo");
    const std::unique_ptr<SimulatorNode> simulator =
        startSimulator(config, world_file, &world, nh, gazebo_nh);
    ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
    while (ros::ok()) simulator->spinOnce(callbacks);
    return 0;
  } catch (const bullet_sim_node::ConfigError& error) {
    ROS_FATAL("%s", error.what());
  } catch (const bullet_sim::LoadError& error) {
    ROS_FATAL("%s", error.what());
  } catch (const std::exception& error) {
    ROS_FATAL("simulation failed: %s", error.what());
  }
  return 1;
}
