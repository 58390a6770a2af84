#include "topics/state_topics.h"

#include "topics/conversions.h"

#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/ModelStates.h>

#include <cmath>

namespace bullet_sim_node {
namespace {

// A subscriber that stalls for a moment at 100x real time must not lose messages.
constexpr uint32_t kQueueSize = 100;
// Absorbs the rounding of sim time (a sum of steps) against the period.
constexpr double kTimeEpsS = 1e-9;

}  // namespace

StateTopics::StateTopics(const bullet_sim::Simulation& sim, PublishQueue& queue,
                         const ros::NodeHandle& gazebo_nh, double rate_hz)
    : sim_(sim), queue_(queue), period_s_(1.0 / rate_hz) {
  ros::NodeHandle nh(gazebo_nh);
  model_states_pub_ =
      CountedPublisher::advertise<gazebo_msgs::ModelStates>(nh, "model_states", kQueueSize);
  link_states_pub_ =
      CountedPublisher::advertise<gazebo_msgs::LinkStates>(nh, "link_states", kQueueSize);
}

void StateTopics::update() {
  const long tick = static_cast<long>(std::floor(sim_.timeS() / period_s_ + kTimeEpsS));
  // Equal: still within the period. Smaller: sim time went back (a reset).
  if (tick == last_tick_) return;
  const bool went_back = tick < last_tick_;
  last_tick_ = tick;
  if (went_back) return;
  if (model_states_pub_.hasSubscribers()) publishModelStates();
  if (link_states_pub_.hasSubscribers()) publishLinkStates();
}

void StateTopics::publishModelStates() const {
  gazebo_msgs::ModelStates msg;
  for (const std::string& robot : sim_.robotNames()) {
    const bullet_sim::EntityState state = sim_.entityState({robot, ""});
    msg.name.push_back(robot);
    msg.pose.push_back(toMsg(state.pose));
    msg.twist.push_back(toMsg(state.twist));
  }
  for (const bullet_sim::StaticModel& model : sim_.world().static_models) {
    msg.name.push_back(model.name);
    msg.pose.push_back(toMsg(model.pose));
    msg.twist.push_back(toMsg(bullet_sim::Twist3{}));
  }
  queue_.publish(model_states_pub_.publisher(), std::move(msg));
}

void StateTopics::publishLinkStates() const {
  gazebo_msgs::LinkStates msg;
  for (const std::string& robot : sim_.robotNames()) {
    for (const std::string& link : sim_.linkNames(robot)) {
      const bullet_sim::EntityState state = sim_.linkState(robot, link);
      msg.name.push_back(robot + "::" + link);
      msg.pose.push_back(toMsg(state.pose));
      msg.twist.push_back(toMsg(state.twist));
    }
  }
  queue_.publish(link_states_pub_.publisher(), std::move(msg));
}

}  // namespace bullet_sim_node
