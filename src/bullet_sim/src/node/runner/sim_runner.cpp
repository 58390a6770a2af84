#include "runner/sim_runner.h"

#include "topics/tf_prefix.h"

#include <malloc.h>

#include <cmath>
#include <utility>

#include <ros/console.h>
#include <rosgraph_msgs/Clock.h>

namespace bullet_sim_node {
namespace {

// /clock goes out at most this often in wall time between sensor readings: enough for
// nodes that sleep on sim time, and cheap when the simulation runs 100x real time.
constexpr std::chrono::milliseconds kClockWallPeriod{1};

// The longest stretch of sim time stepped between two looks at the node's callbacks, when
// the node runs behind the wall clock or unpaced: a Burger's IMU (200 Hz) ends every round
// sooner. Gazebo's diff drive reads its command at its update rate (30 Hz for a Burger), so
// a command waiting up to this is unseen.
constexpr double kRoundS = 0.005;

}  // namespace

SimRunner::SimRunner(bullet_sim::Simulation& sim, const ros::NodeHandle& nh,
                     const ros::NodeHandle& gazebo_nh, bool paused, double model_states_rate_hz,
                     bool state_topics, std::function<double()> real_time_factor)
    : sim_(sim),
      nh_(nh),
      // Paused, Gazebo's world does not step on while a frame renders.
      cameras_(sim, queue_,
               [this, real_time_factor = std::move(real_time_factor)] {
                 return paused_ ? 0.0 : real_time_factor();
               }),
      paused_(paused) {
  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  if (state_topics) {
    state_topics_ = std::make_unique<StateTopics>(sim, queue_, gazebo_nh, model_states_rate_hz);
  }
  // The world's own models (those that move, or carry sensors) are simulated from the
  // start and publish in the node's namespace, as Gazebo's plugins of a world's models do
  // in theirs: their cameras, and their other sensors and plugins (not their joint
  // states, which Gazebo publishes only through a plugin).
  const std::string tf_prefix = findTfPrefix(nh_);
  for (const std::string& name : sim_.robotNames()) {
    cameras_.addRobot(name, nh_, tf_prefix);
    if (RobotIo::hasTopics(sim_.robotSpec(name))) {
      robots_[name] = std::make_unique<RobotIo>(sim_, queue_, name, nh_, tf_prefix, false);
    }
  }
}

void SimRunner::spawn(const std::string& name, const bullet_sim::RobotSpec& spec,
                      const bullet_sim::Pose3& pose, const std::string& robot_namespace) {
  // The namespace first: an invalid one throws before the simulation holds the robot.
  const ros::NodeHandle robot_nh(nh_, robot_namespace);
  sim_.spawnRobot(name, spec, pose);
  logSimulationWarnings();
  try {
    const std::string tf_prefix = findTfPrefix(robot_nh);
    robots_[name] = std::make_unique<RobotIo>(sim_, queue_, name, robot_nh, tf_prefix);
    cameras_.addRobot(name, robot_nh, tf_prefix);
    if (!tf_prefix.empty()) {
      ROS_INFO("model %s: topics in %s, frames under tf_prefix '%s'", name.c_str(),
               robot_nh.getNamespace().c_str(), tf_prefix.c_str());
    }
  } catch (const ros::InvalidNameException&) {  // a topic name of the robot's Gazebo tags
    robots_.erase(name);
    cameras_.removeRobot(name);
    sim_.deleteRobot(name);
    throw;
  }
  spawn_poses_[name] = pose;
  releaseParserMemory();
}

void releaseParserMemory() {
  // Parsing a model or world (urdfdom's and tinyxml2's element trees) frees
  // megabytes in small blocks that glibc keeps for reuse; the simulation never needs
  // them again, so they go back to the system.
  malloc_trim(0);
}

bool SimRunner::remove(const std::string& name) {
  if (!sim_.deleteRobot(name)) return false;
  robots_.erase(name);
  cameras_.removeRobot(name);
  spawn_poses_.erase(name);
  return true;
}

const bullet_sim::Pose3& SimRunner::spawnPose(const std::string& name) const {
  return spawn_poses_.at(name);
}

unsigned SimRunner::roundSteps() const {
  const double steps = std::floor(kRoundS / sim_.physicsStepS() + 1e-9);
  return steps >= 1 ? static_cast<unsigned>(steps) : 1u;
}

unsigned SimRunner::step(unsigned max_steps) {
  // The step's messages wake the publishing thread once, when they are all queued.
  const PublishQueue::Batch batch(queue_);
  unsigned taken = 0;
  const std::vector<bullet_sim::DueSensor> due = sim_.stepToNextReading(max_steps, &taken);
  const auto now = std::chrono::steady_clock::now();
  // A reading stamped t goes out after the clock says t, so no listener sees the future.
  if (!due.empty() || now - last_clock_wall_ >= kClockWallPeriod) publishClock();
  // The wanted scans are cast together, and the cameras' frames rendered together, on the
  // physics threads.
  std::vector<bullet_sim::DueSensor> scans_due, cameras_due;
  std::vector<RobotIo*> scan_ios;
  for (const bullet_sim::DueSensor& sensor : due) {
    if (sensor.kind == bullet_sim::SensorKind::Camera) {
      cameras_due.push_back(sensor);
      continue;
    }
    const auto robot = robots_.find(sensor.robot);
    if (robot == robots_.end()) continue;
    if (sensor.kind != bullet_sim::SensorKind::Ray) {
      robot->second->publish(sensor);
    } else if (robot->second->wantsScan(sensor.index)) {
      scans_due.push_back(sensor);
      scan_ios.push_back(robot->second.get());
    }
  }
  if (!cameras_due.empty()) cameras_.publish(cameras_due);
  if (!scans_due.empty()) {
    const std::vector<bullet_sim::LaserScanData> scans = sim_.readRays(scans_due);
    for (size_t i = 0; i < scans.size(); ++i) {
      scan_ios[i]->publishScan(scans_due[i].index, scans[i]);
    }
  }
  if (state_topics_) state_topics_->update();
  logSimulationWarnings();  // e.g. a command scaled to the wheels' limits
  return taken;
}

void SimRunner::logSimulationWarnings() {
  for (const std::string& warning : sim_.takeWarnings()) ROS_WARN("%s", warning.c_str());
}

void SimRunner::publishClock() {
  rosgraph_msgs::Clock clock;
  clock.clock.fromSec(sim_.timeS());
  queue_.publish(clock_pub_, clock);
  last_clock_wall_ = std::chrono::steady_clock::now();
}

}  // namespace bullet_sim_node
