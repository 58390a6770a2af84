// Sends the stepping thread's messages from a thread of their own.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include <ros/publisher.h>

namespace bullet_sim_node {

/// A FIFO of publish calls run by one thread, so that the stepping thread only steps and
/// reads sensors: filling and serialising messages and waking roscpp's sending thread
/// (a system call per message) happen beside it, as gazebo_ros's plugins hand their
/// messages to a publishing thread (PubMultiQueue). Messages leave in the order they were
/// queued. When `capacity` calls wait, push() waits too: a simulation running faster than
/// its messages can leave slows down instead of queueing without bound.
class PublishQueue {
 public:
  explicit PublishQueue(size_t capacity = 1024);
  /// Sends what is queued, then stops the thread.
  ~PublishQueue();
  PublishQueue(const PublishQueue&) = delete;
  PublishQueue& operator=(const PublishQueue&) = delete;

  void push(std::function<void()> publish);
  /// Queues `publisher.publish(message)`; `message` is a message or a shared pointer to one.
  template <class Message>
  void publish(const ros::Publisher& publisher, Message message) {
    push([publisher, m = std::move(message)] { publisher.publish(m); });
  }
  /// Returns when every call queued before it has run.
  void flush();

 private:
  void run();

  const size_t capacity_;
  std::mutex mutex_;
  std::condition_variable work_;   ///< the thread waits for calls
  std::condition_variable space_;  ///< push() and flush() wait for the thread
  std::deque<std::function<void()>> calls_;
  bool running_call_ = false;
  bool consumer_waiting_ = false;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace bullet_sim_node
