// Steps the simulation and hands what falls due to the ROS side: /clock and robot sensors.
#pragma once

#include "topics/camera_io.h"
#include "topics/publish_queue.h"
#include "topics/robot_io.h"
#include "topics/state_topics.h"

#include <bullet_sim/simulation.h>

#include <ros/node_handle.h>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace bullet_sim_node {

/// Owns the robots' ROS adapters, the /clock publisher and the model and link state
/// topics (in `gazebo_nh`) around one Simulation. Everything runs on the node's stepping
/// thread (services and subscribers are called between steps), so nothing here is locked;
/// the messages it makes leave from the publishing thread of a PublishQueue, in order.
class SimRunner {
 public:
  /// Without `state_topics`, /gazebo/model_states and link_states are not advertised
  /// (enable_ros_network false). `real_time_factor()` reads the pace: the sim time a
  /// render takes in Gazebo (CameraIo), none while paused.
  SimRunner(bullet_sim::Simulation& sim, const ros::NodeHandle& nh,
            const ros::NodeHandle& gazebo_nh, bool paused, double model_states_rate_hz,
            bool state_topics, std::function<double()> real_time_factor);

  /// Adds a robot to the simulation and advertises its topics under `robot_namespace`;
  /// its frames get the tf_prefix found from that namespace.
  /// Throws bullet_sim::LoadError as Simulation::spawnRobot does, ros::InvalidNameException
  /// for an invalid namespace or topic name; either way nothing is added.
  void spawn(const std::string& name, const bullet_sim::RobotSpec& spec,
             const bullet_sim::Pose3& pose, const std::string& robot_namespace);
  bool remove(const std::string& name);
  /// The pose a robot was spawned at (reset_world puts it back there).
  const bullet_sim::Pose3& spawnPose(const std::string& name) const;

  /// Advances the simulation to its next sensor reading, `max_steps` physics steps at
  /// most (Simulation::stepToNextReading), and publishes /clock and every due, subscribed
  /// sensor. Returns the steps taken.
  unsigned step(unsigned max_steps);
  /// The most steps the node takes at once (kRoundS of sim time): commands and service
  /// calls take effect between them.
  unsigned roundSteps() const;
  /// Logs, once each, what the simulation noticed while building models.
  void logSimulationWarnings();
  /// Publishes the current sim time on /clock.
  void publishClock();
  /// Returns when every message made so far has been handed to roscpp.
  void flushMessages() { queue_.flush(); }

  bool paused() const { return paused_; }
  void setPaused(bool paused) { paused_ = paused; }
  bullet_sim::Simulation& sim() { return sim_; }

 private:
  bullet_sim::Simulation& sim_;
  /// First: the adapters below queue publish calls on it (it sends what is queued when
  /// it goes; the calls hold their publishers).
  PublishQueue queue_;
  ros::NodeHandle nh_;
  ros::Publisher clock_pub_;
  std::map<std::string, std::unique_ptr<RobotIo>> robots_;
  CameraIo cameras_;
  std::unique_ptr<StateTopics> state_topics_;  ///< null without the ROS network
  std::map<std::string, bullet_sim::Pose3> spawn_poses_;
  std::chrono::steady_clock::time_point last_clock_wall_;
  bool paused_;
};

/// Returns the memory that parsing a world or model freed to the system.
void releaseParserMemory();

}  // namespace bullet_sim_node
