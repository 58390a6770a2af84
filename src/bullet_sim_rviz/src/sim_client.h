// The panel's and the place tool's link to the simulator: its services and /clock.
#pragma once

#include "bullet_sim_rviz/rtf_estimator.h"
#include "bullet_sim_rviz/sim_snapshot.h"

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>
#include <rosgraph_msgs/Clock.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace bullet_sim_rviz {

/// Talks to the simulator only through gazebo_ros's services under /gazebo (and
/// bullet_sim's step_simulation) and /clock. Service calls run one after another on a
/// worker thread, so a slow or absent simulator never freezes RViz; when idle, the worker
/// looks once a second whether the simulator is there and reads its models and physics.
class SimClient {
 public:
  /// Receives a request's outcome on the worker thread: success and a line for the user.
  using Done = std::function<void(bool ok, const std::string& text)>;

  /// The one client of this RViz process, shared by the panel and the place tool (which
  /// robot to place is chosen in the panel).
  static std::shared_ptr<SimClient> shared();
  ~SimClient();

  SimSnapshot snapshot() const;

  void pause(Done done);
  void play(Done done);
  /// Pauses, then advances exactly `steps` physics steps.
  void step(uint32_t steps, Done done);
  void resetWorld(Done done);
  void resetSimulation(Done done);
  void setRealTimeFactor(double factor, Done done);
  /// Moves `model` to (x, y) in the world, heading `yaw_rad`, at rest; keeps its height.
  void place(const std::string& model, double x_m, double y_m, double yaw_rad, Done done);

  void selectModel(const std::string& model);
  /// The panel's choice, or the only model when nothing is chosen; "" when unknown.
  std::string targetModel() const;

 private:
  SimClient();
  void submit(std::function<void()> job);
  void work();
  void refresh();
  void onClock(const rosgraph_msgs::Clock& clock);

  ros::CallbackQueue queue_;
  ros::NodeHandle nh_;
  ros::Subscriber clock_sub_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;

  mutable std::mutex mutex_;  ///< guards everything below
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  SimSnapshot state_;
  RtfEstimator rtf_;
  std::string selected_model_;
  std::thread worker_;
};

}  // namespace bullet_sim_rviz
