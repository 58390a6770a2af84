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

#include <malloc.h>

#include <atomic>
#include <future>
#include <memory>
#include <string>
#include <thread>

namespace {

using bullet_sim_node::Config;
using bullet_sim_node::SimulatorNode;

/// The world file named on the command line, loaded on a thread of its own so that it is
/// read while roscpp starts (its XML-RPC server, /rosout, the parameters). The spec is
/// handed over as soon as it is read; the thread then frees the parser's documents while
/// the simulator starts, and once it has ended, finish() gives the memory back to the
/// system.
class WorldPreload {
 public:
  explicit WorldPreload(const std::string& world_file) : file_(world_file) {
    if (file_.empty()) return;
    spec_ = promise_.get_future();
    thread_ = std::thread([this] { load(); });
  }
  ~WorldPreload() {
    if (thread_.joinable()) thread_.join();
  }
  WorldPreload(const WorldPreload&) = delete;
  WorldPreload& operator=(const WorldPreload&) = delete;

  const std::string& file() const { return file_; }
  /// Once the thread has freed the documents and ended: joins it and gives what the load
  /// left free back to the system (the thread's arena too). Does not wait for it.
  void finish() {
    if (!thread_.joinable() || !ended_.load(std::memory_order_acquire)) return;
    thread_.join();
    malloc_trim(0);
  }
  /// Valid until get() is called, when a file was named.
  std::future<bullet_sim::WorldSpec>& spec() { return spec_; }

 private:
  void load() {
    std::shared_ptr<const void> documents;
    try {
      promise_.set_value(bullet_sim::loadWorldFile(
          file_, bullet_sim::UriResolver(bullet_sim::ResourcePaths::fromEnvironment()),
          &documents));
    } catch (...) {
      promise_.set_exception(std::current_exception());
    }
    documents.reset();
    ended_.store(true, std::memory_order_release);
  }

  std::string file_;
  std::promise<bullet_sim::WorldSpec> promise_;
  std::future<bullet_sim::WorldSpec> spec_;
  std::atomic<bool> ended_{false};
  std::thread thread_;
};

/// The simulator, with the preloaded world when its file is the one
/// ~world_file names.
std::unique_ptr<SimulatorNode> startSimulator(const Config& config, WorldPreload* preload,
                                              const ros::NodeHandle& nh,
                                              const ros::NodeHandle& gazebo_nh) {
  if (preload->spec().valid() && config.world_file == preload->file()) {
    return std::make_unique<SimulatorNode>(config, preload->spec().get(), nh, gazebo_nh);
  }
  return std::make_unique<SimulatorNode>(config, nh, gazebo_nh);
}

}  // namespace

int main(int argc, char** argv) {
  bullet_sim_node::collectExportedModelPaths();
  WorldPreload preload(bullet_sim_node::commandLineWorldFile(argc, argv));
  ros::init(argc, argv, "bullet_sim");
  ros::NodeHandle nh;  // outlives the messages below: its end shuts roscpp's console down
  try {
    const Config config = bullet_sim_node::readConfig(nh, ros::NodeHandle("~"));
    const ros::NodeHandle gazebo_nh("/gazebo");
    const std::unique_ptr<SimulatorNode> simulator =
        startSimulator(config, &preload, nh, gazebo_nh);
    ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
    while (ros::ok()) {
      simulator->spinOnce(callbacks);
      preload.finish();
    }
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
