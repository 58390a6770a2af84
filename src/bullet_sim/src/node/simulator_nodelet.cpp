// bullet_sim/Simulator: the simulator of bullet_sim_node as a nodelet. Nodelets in the same
// manager receive its messages as the shared pointers it publishes: no serialisation, no
// copy, no socket (point clouds and images above all).
#include "config.h"
#include "gazebo_paths.h"
#include "simulator_node.h"

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/callback_queue.h>
#include <ros/node_handle.h>

#include <atomic>
#include <exception>
#include <memory>
#include <thread>

namespace bullet_sim_node {

/// Loads the world in onInit (a failure there fails the load, with the node's message),
/// then steps on a thread of its own. Its services and subscribers are called by that
/// thread between steps, as in the node, never by the manager's worker threads.
class SimulatorNodelet : public nodelet::Nodelet {
 public:
  ~SimulatorNodelet() override {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }

 private:
  void onInit() override {
    collectExportedModelPaths();
    ros::NodeHandle nh = getNodeHandle();
    ros::NodeHandle private_nh = getPrivateNodeHandle();
    nh.setCallbackQueue(&callbacks_);
    private_nh.setCallbackQueue(&callbacks_);
    // With the nodelet's remappings and callback queue, as the node's /gazebo has the node's.
    const ros::NodeHandle gazebo_nh(nh, "/gazebo");
    try {
      const Config config = readConfig(nh, private_nh);
      simulator_ = std::make_unique<SimulatorNode>(config, nh, gazebo_nh);
    } catch (const std::exception& error) {
      // The loader fails the load on the exception but does not say why.
      NODELET_FATAL("%s: %s", getName().c_str(), error.what());
      throw;
    }
    thread_ = std::thread([this] {
      try {
        while (!stop_ && ros::ok()) simulator_->spinOnce(callbacks_);
      } catch (const std::exception& error) {
        // The node would exit; a nodelet must leave its manager running.
        NODELET_FATAL("simulation failed, stepping stopped: %s", error.what());
      }
    });
  }

  ros::CallbackQueue callbacks_;
  std::unique_ptr<SimulatorNode> simulator_;  ///< after the queue: goes before it
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace bullet_sim_node

PLUGINLIB_EXPORT_CLASS(bullet_sim_node::SimulatorNodelet, nodelet::Nodelet)
