// /gazebo/model_states and /gazebo/link_states.
#pragma once

#include <bullet_sim/simulation.h>

#include "topics/counted_publisher.h"
#include "topics/publish_queue.h"

#include <ros/node_handle.h>
#include <ros/publisher.h>

namespace bullet_sim_node {

/// Publishes gazebo_msgs/ModelStates (every robot's root link) and gazebo_msgs/LinkStates
/// (every link, named "model::link"), poses and twists in the world frame, at `rate_hz`
/// in sim time. A topic nobody subscribes to is not filled at all.
class StateTopics {
 public:
  /// Messages leave through `queue`; `sim` and `queue` must outlive this object.
  StateTopics(const bullet_sim::Simulation& sim, PublishQueue& queue,
              const ros::NodeHandle& gazebo_nh, double rate_hz);

  /// Publishes at every multiple of the period in sim time (0.01, 0.02, ... s at 100 Hz)
  /// that the last step reached. Call after every step.
  void update();

 private:
  void publishModelStates() const;
  void publishLinkStates() const;

  const bullet_sim::Simulation& sim_;
  PublishQueue& queue_;
  CountedPublisher model_states_pub_, link_states_pub_;
  const double period_s_;
  long last_tick_ = 0;  ///< periods elapsed at the last message
};

}  // namespace bullet_sim_node
