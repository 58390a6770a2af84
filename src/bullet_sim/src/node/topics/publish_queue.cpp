#include "topics/publish_queue.h"

#include <pthread.h>
#include <ros/console.h>

#include <exception>
#include <utility>

namespace bullet_sim_node {

PublishQueue::PublishQueue(size_t capacity, std::chrono::microseconds linger)
    : capacity_(capacity), linger_(linger), thread_(&PublishQueue::run, this) {}

PublishQueue::~PublishQueue() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  work_.notify_one();
  thread_.join();
}

PublishQueue::Batch::Batch(PublishQueue& queue) : queue_(queue) {
  std::lock_guard<std::mutex> lock(queue_.mutex_);
  ++queue_.batches_;
}

PublishQueue::Batch::~Batch() {
  std::unique_lock<std::mutex> lock(queue_.mutex_);
  if (--queue_.batches_ == 0 && !queue_.calls_.empty()) queue_.wakeIfSleeping(lock);
}

void PublishQueue::wakeIfSleeping(std::unique_lock<std::mutex>& lock) {
  // Waking the thread is a system call: only when it sleeps.
  if (!consumer_waiting_) return;
  consumer_waiting_ = false;
  lock.unlock();
  work_.notify_one();
}

void PublishQueue::wakeNow() {
  if (lingering_) wake_requested_ = true;
  if (!lingering_ && !consumer_waiting_) return;  // it is running calls
  consumer_waiting_ = false;
  work_.notify_one();
}

void PublishQueue::push(std::function<void()> publish) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (calls_.size() >= capacity_) {
    wakeNow();  // it may be held back by a Batch or a linger: it must make room
    space_.wait(lock, [this] { return calls_.size() < capacity_; });
  }
  calls_.push_back(std::move(publish));
  if (batches_ == 0) wakeIfSleeping(lock);
}

void PublishQueue::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (calls_.empty() && !running_call_) return;
  wakeNow();
  space_.wait(lock, [this] { return calls_.empty() && !running_call_; });
}

void PublishQueue::run() {
  pthread_setname_np(pthread_self(), "sim_publish");  // for top -H, perf and /proc
  using Clock = std::chrono::steady_clock;
  bool linger = false;  // the last calls came within a linger of the queue running dry
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (calls_.empty()) {
      if (stop_) return;
      space_.notify_all();  // flush() waits for an empty queue
      if (linger) {
        // Pushes do not wake a lingering thread; it looks again when the linger ends.
        lingering_ = true;
        work_.wait_for(lock, linger_, [this] { return stop_ || wake_requested_; });
        lingering_ = false;
        wake_requested_ = false;
        if (!calls_.empty() || stop_) continue;
      }
      const Clock::time_point dry = Clock::now();
      consumer_waiting_ = true;
      work_.wait(lock, [this] { return !calls_.empty() || stop_; });
      consumer_waiting_ = false;
      linger = Clock::now() - dry < linger_;
      continue;
    }
    std::function<void()> call = std::move(calls_.front());
    calls_.pop_front();
    const bool was_full = calls_.size() + 1 == capacity_;
    running_call_ = true;
    lock.unlock();
    if (was_full) space_.notify_all();
    try {
      call();
    } catch (const std::exception& error) {
      ROS_ERROR("publishing failed: %s", error.what());
    }
    lock.lock();
    running_call_ = false;
  }
}

}  // namespace bullet_sim_node
