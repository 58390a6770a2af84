// Sends the stepping thread's messages from a thread of their own.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/publisher.h>

namespace bullet_sim_node {

/// A FIFO of publish calls run by one thread, so that the stepping thread only steps and
/// reads sensors: filling and serialising messages and waking roscpp's sending thread
/// (a system call per message) happen beside it, as gazebo_ros's plugins hand their
/// messages to a publishing thread (PubMultiQueue). Messages leave in the order they were
/// queued. When `capacity` calls wait, push() waits too: a simulation running faster than
/// its messages can leave slows down instead of queueing without bound.
///
/// When calls come within `linger` of the queue running dry, the thread lingers that long
/// the next time it runs dry before it sleeps until a push wakes it, and pushes do not wake
/// a lingering thread: while calls keep coming that fast (a simulation far faster than
/// real time) they leave in batches every `linger`, and the stepping thread makes no
/// system call to wake the thread for each burst. When they come further apart (real
/// time), the thread sleeps as soon as the queue runs dry and each push wakes it at once.
class PublishQueue {
 public:
  static constexpr std::chrono::microseconds kDefaultLinger{100};

  explicit PublishQueue(size_t capacity = 1024,
                        std::chrono::microseconds linger = kDefaultLinger);
  /// Sends what is queued, then stops the thread.
  ~PublishQueue();
  PublishQueue(const PublishQueue&) = delete;
  PublishQueue& operator=(const PublishQueue&) = delete;

  /// While a Batch lives, pushes do not wake a sleeping thread (unless the queue is full);
  /// its end does, once, if calls wait. A step's messages, all stamped with the step's
  /// time, cost one wake-up however many robots made them.
  class Batch {
   public:
    explicit Batch(PublishQueue& queue);
    ~Batch();
    Batch(const Batch&) = delete;
    Batch& operator=(const Batch&) = delete;

   private:
    PublishQueue& queue_;
  };

  void push(std::function<void()> publish);
  /// Queues `publisher.publish(message)`. A message is published as a shared pointer, so
  /// that subscribers in the same process (nodelets) get it without serialisation or copy;
  /// nothing may change it once queued.
  template <class Message>
  void publish(const ros::Publisher& publisher, boost::shared_ptr<Message> message) {
    push([publisher, m = std::move(message)] { publisher.publish(m); });
  }
  template <class Message>
  void publish(const ros::Publisher& publisher, Message message) {
    publish(publisher, boost::make_shared<const Message>(std::move(message)));
  }
  /// Returns when every call queued before it has run (without waiting for a linger).
  void flush();

 private:
  void run();
  /// Wakes the thread when it sleeps (with `mutex_` held by `lock`, which it releases).
  void wakeIfSleeping(std::unique_lock<std::mutex>& lock);
  /// Wakes the thread when it sleeps or lingers (with `mutex_` held).
  void wakeNow();

  const size_t capacity_;
  const std::chrono::microseconds linger_;
  std::mutex mutex_;
  std::condition_variable work_;   ///< the thread waits for calls
  std::condition_variable space_;  ///< push() and flush() wait for the thread
  std::deque<std::function<void()>> calls_;
  bool running_call_ = false;
  bool consumer_waiting_ = false;  ///< asleep until a push wakes it
  bool lingering_ = false;         ///< waiting for the end of a linger
  bool wake_requested_ = false;    ///< flush() cuts the linger short
  int batches_ = 0;                ///< open Batches: pushes do not wake the thread
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace bullet_sim_node
