// A publisher that knows whether anyone subscribes without asking roscpp each time.
#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <atomic>
#include <memory>
#include <string>

namespace bullet_sim_node {

/// A ros::Publisher whose connect and disconnect callbacks count its subscribers, as
/// gazebo_ros's sensor plugins count theirs. Publisher::getNumSubscribers takes roscpp's
/// topic-manager lock, which every publish of the node holds while it serialises a message
/// and hands it to the subscribers' connections; asked on the stepping thread for every due
/// sensor, it made the steps wait for the publishing thread. The callbacks run from the
/// callback queue of the node handle that advertised the topic (the stepping thread calls
/// it before each step), so a new subscriber is counted before the next step's readings.
class CountedPublisher {
 public:
  CountedPublisher() = default;

  template <class Message>
  static CountedPublisher advertise(ros::NodeHandle& nh, const std::string& topic,
                                    uint32_t queue_size, bool latch = false) {
    CountedPublisher out;
    auto count = std::make_shared<std::atomic<int>>(0);
    out.count_ = count;
    out.publisher_ = nh.advertise<Message>(
        topic, queue_size,
        [count](const ros::SingleSubscriberPublisher&) { count->fetch_add(1); },
        [count](const ros::SingleSubscriberPublisher&) { count->fetch_sub(1); },
        ros::VoidConstPtr(), latch);
    return out;
  }

  /// Whether a subscriber is connected (false for a publisher never advertised).
  bool hasSubscribers() const { return count_ && count_->load(std::memory_order_relaxed) > 0; }
  const ros::Publisher& publisher() const { return publisher_; }
  explicit operator bool() const { return static_cast<bool>(publisher_); }

 private:
  ros::Publisher publisher_;
  std::shared_ptr<std::atomic<int>> count_;
};

}  // namespace bullet_sim_node
