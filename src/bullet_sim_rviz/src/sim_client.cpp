#include "sim_client.h"

#include "bullet_sim_rviz/physics_rate.h"

#include <bullet_sim/StepSimulation.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <ros/service.h>
#include <std_srvs/Empty.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace bullet_sim_rviz {
namespace {

const char* const kPause = "/gazebo/pause_physics";
const char* const kUnpause = "/gazebo/unpause_physics";
const char* const kStep = "/gazebo/step_simulation";
const char* const kResetWorld = "/gazebo/reset_world";
const char* const kResetSimulation = "/gazebo/reset_simulation";
const char* const kGetPhysics = "/gazebo/get_physics_properties";
const char* const kSetPhysics = "/gazebo/set_physics_properties";
const char* const kWorldProperties = "/gazebo/get_world_properties";
const char* const kGetModelState = "/gazebo/get_model_state";
const char* const kSetModelState = "/gazebo/set_model_state";

// How often the idle worker looks for the simulator: a panel shows a started or stopped
// simulator within this time.
constexpr std::chrono::milliseconds kRefreshPeriod{1000};
// A paused simulator still publishes /clock, at the same time: still this long = paused.
constexpr double kStillClockS = 0.3;

double wallNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

bool callEmpty(const char* name, std::string* text) {
  std_srvs::Empty srv;
  if (ros::service::call(name, srv)) return true;
  *text = std::string(name) + " failed: is the simulator running?";
  return false;
}

/// Reports a Gazebo-style (success, status_message) answer as (ok, text).
template <typename Response>
bool answered(bool called, const char* name, const Response& res, std::string* text) {
  if (!called) {
    *text = std::string(name) + " failed: is the simulator running?";
    return false;
  }
  if (!res.success) *text = std::string(name) + ": " + res.status_message;
  return res.success;
}

}  // namespace

std::shared_ptr<SimClient> SimClient::shared() {
  static std::mutex mutex;
  static std::weak_ptr<SimClient> instance;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<SimClient> client = instance.lock();
  if (!client) {
    client.reset(new SimClient());
    instance = client;
  }
  return client;
}

SimClient::SimClient() {
  nh_.setCallbackQueue(&queue_);
  clock_sub_ = nh_.subscribe("/clock", 10, &SimClient::onClock, this);
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
  worker_ = std::thread(&SimClient::work, this);
}

SimClient::~SimClient() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  worker_.join();
  spinner_->stop();
}

SimSnapshot SimClient::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  SimSnapshot s = state_;
  s.measured_rtf = rtf_.factor(wallNow());
  s.clock_stalled = rtf_.stalled(wallNow(), kStillClockS);
  return s;
}

void SimClient::onClock(const rosgraph_msgs::Clock& clock) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.sim_time_s = clock.clock.toSec();
  rtf_.addSample(wallNow(), clock.clock.toSec());
}

void SimClient::submit(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    jobs_.push_back(std::move(job));
  }
  wake_.notify_all();
}

void SimClient::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    if (jobs_.empty()) {
      lock.unlock();
      refresh();
      lock.lock();
      wake_.wait_for(lock, kRefreshPeriod, [this] { return stopping_ || !jobs_.empty(); });
      continue;
    }
    std::function<void()> job = std::move(jobs_.front());
    jobs_.pop_front();
    lock.unlock();
    job();
    refresh();
    lock.lock();
  }
}

void SimClient::refresh() {
  SimSnapshot found;
  found.services_available = ros::service::exists(kPause, false);
  if (found.services_available) {
    gazebo_msgs::GetWorldProperties world;
    if (ros::service::call(kWorldProperties, world) && world.response.success)
      found.models = world.response.model_names;
    gazebo_msgs::GetPhysicsProperties physics;
    if (ros::service::call(kGetPhysics, physics) && physics.response.success) {
      found.paused = physics.response.pause;
      if (physics.response.time_step > 0)
        found.target_rtf =
            realTimeFactorOf(physics.response.max_update_rate, physics.response.time_step);
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  state_.services_available = found.services_available;
  state_.models = found.models;
  state_.paused = found.paused;
  state_.target_rtf = found.target_rtf;
}

void SimClient::pause(Done done) {
  submit([done] {
    std::string text = "paused";
    const bool ok = callEmpty(kPause, &text);
    done(ok, text);
  });
}

void SimClient::play(Done done) {
  submit([done] {
    std::string text = "playing";
    const bool ok = callEmpty(kUnpause, &text);
    done(ok, text);
  });
}

void SimClient::step(uint32_t steps, Done done) {
  submit([done, steps] {
    std::string text;
    if (!callEmpty(kPause, &text)) return done(false, text);
    bullet_sim::StepSimulation srv;
    srv.request.steps = steps;
    const bool ok = answered(ros::service::call(kStep, srv), kStep, srv.response, &text);
    if (ok) text = "stepped " + std::to_string(steps) + " to " + simTimeText(srv.response.sim_time.toSec());
    done(ok, text);
  });
}

void SimClient::resetWorld(Done done) {
  submit([done] {
    std::string text = "world reset: models back at their start poses";
    const bool ok = callEmpty(kResetWorld, &text);
    done(ok, text);
  });
}

void SimClient::resetSimulation(Done done) {
  submit([done] {
    std::string text = "simulation reset: time 0, models at their start poses";
    const bool ok = callEmpty(kResetSimulation, &text);
    done(ok, text);
  });
}

void SimClient::setRealTimeFactor(double factor, Done done) {
  submit([done, factor] {
    std::string text;
    gazebo_msgs::GetPhysicsProperties get;
    if (!answered(ros::service::call(kGetPhysics, get), kGetPhysics, get.response, &text))
      return done(false, text);
    gazebo_msgs::SetPhysicsProperties set;
    set.request.time_step = get.response.time_step;
    set.request.gravity = get.response.gravity;
    set.request.ode_config = get.response.ode_config;
    try {
      set.request.max_update_rate = maxUpdateRateFor(factor, get.response.time_step);
    } catch (const std::invalid_argument& error) {
      return done(false, error.what());
    }
    const bool ok = answered(ros::service::call(kSetPhysics, set), kSetPhysics, set.response, &text);
    if (ok) text = factor > 0 ? "real-time factor set to " + rtfText(factor)
                              : std::string("running as fast as possible");
    done(ok, text);
  });
}

void SimClient::place(const std::string& model, double x_m, double y_m, double yaw_rad,
                      Done done) {
  submit([done, model, x_m, y_m, yaw_rad] {
    std::string text;
    gazebo_msgs::GetModelState get;
    get.request.model_name = model;
    if (!answered(ros::service::call(kGetModelState, get), kGetModelState, get.response, &text))
      return done(false, text);
    gazebo_msgs::SetModelState set;
    gazebo_msgs::ModelState& state = set.request.model_state;
    state.model_name = model;
    state.reference_frame = "world";
    state.pose.position.x = x_m;
    state.pose.position.y = y_m;
    state.pose.position.z = get.response.pose.position.z;
    state.pose.orientation.z = std::sin(0.5 * yaw_rad);
    state.pose.orientation.w = std::cos(0.5 * yaw_rad);
    const bool ok =
        answered(ros::service::call(kSetModelState, set), kSetModelState, set.response, &text);
    if (ok) {
      char where[96];
      std::snprintf(where, sizeof where, " placed at x %.3f m, y %.3f m, yaw %.1f deg", x_m, y_m,
                    yaw_rad * 180.0 / M_PI);
      text = model + where;
    }
    done(ok, text);
  });
}

void SimClient::selectModel(const std::string& model) {
  std::lock_guard<std::mutex> lock(mutex_);
  selected_model_ = model;
}

std::string SimClient::targetModel() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!selected_model_.empty()) return selected_model_;
  return state_.models.size() == 1 ? state_.models.front() : std::string();
}

}  // namespace bullet_sim_rviz
