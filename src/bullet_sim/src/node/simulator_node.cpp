#include "simulator_node.h"

#include <bullet_sim/description/robot_spec.h>
#include <bullet_sim/description/world_spec.h>

#include <ros/console.h>
#include <ros/param.h>

#include <string>
#include <vector>

namespace bullet_sim_node {
namespace {

void logWarnings(const std::string& source, const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) ROS_WARN("%s: %s", source.c_str(), warning.c_str());
}

void spawnStartRobot(const Config& config, SimRunner* runner) {
  const bullet_sim::RobotSpec robot =
      bullet_sim::parseRobot(config.robot_description, "robot_description");
  logWarnings("robot_description", robot.warnings);
  bullet_sim::Pose3 pose;
  pose.position = {config.spawn_x_m, config.spawn_y_m, 0.0};
  pose.orientation = Eigen::AngleAxisd(config.spawn_yaw_rad, Eigen::Vector3d::UnitZ());
  runner->spawn(config.robot_name, robot, pose, "");
}

}  // namespace

SimulatorNode::SimulatorNode(const Config& config, const ros::NodeHandle& nh,
                             const ros::NodeHandle& gazebo_nh)
    : SimulatorNode(config, bullet_sim::loadWorldFile(config.world_file), nh, gazebo_nh) {}

SimulatorNode::SimulatorNode(const Config& config, const bullet_sim::WorldSpec& world,
                             const ros::NodeHandle& nh, const ros::NodeHandle& gazebo_nh)
    : pacer_(config.real_time_factor), gazebo_nh_(gazebo_nh) {
  // The world's warnings name their file (and model, link) themselves.
  for (const std::string& warning : world.warnings) ROS_WARN("%s", warning.c_str());
  bullet_sim::SimConfig sim_config;
  sim_config.physics_step_s =
      config.physics_step_s > 0 ? config.physics_step_s : world.max_step_size_s;
  sim_config.seed = static_cast<uint64_t>(config.seed);
  sim_config.threads = static_cast<unsigned>(config.threads);
  sim_config.cmd_vel_timeout_s = config.cmd_vel_timeout_s;
  sim_ = std::make_unique<bullet_sim::Simulation>(world, sim_config);
  runner_ = std::make_unique<SimRunner>(*sim_, nh, gazebo_nh, config.start_paused,
                                        config.model_states_rate_hz, config.enable_ros_network,
                                        [this] { return pacer_.realTimeFactor(); });
  runner_->logSimulationWarnings();  // how the world's movable models were built
  releaseParserMemory();
  if (!config.robot_name.empty()) spawnStartRobot(config, runner_.get());
  status_ = std::make_unique<StatusReporter>(*sim_, config.status_period_s);
  for (const bullet_sim::WorldModel& model : world.models) world_models_.push_back(model.name);
  if (config.enable_ros_network) {
    // gazebo_ros's API; without it (as gazebo_ros does) only /clock and the robots' topics.
    physics_services_ = std::make_unique<PhysicsServices>(*runner_, pacer_, gazebo_nh,
                                                          config.step_service);
    model_services_ = std::make_unique<ModelServices>(*runner_, gazebo_nh,
                                                      config.spawn_model_service);
    link_joint_services_ = std::make_unique<LinkJointServices>(*runner_, gazebo_nh);
    property_services_ = std::make_unique<PropertyServices>(*runner_, gazebo_nh);
    physics_reconfigure_ = std::make_unique<PhysicsReconfigure>(*physics_services_, gazebo_nh);
    physics_services_->onChange([this] { physics_reconfigure_->publishCurrent(); });
    markers_param_ = config.markers_param;
    updateMarkers();
  } else {
    ROS_INFO("enable_ros_network is false: no /gazebo service or topic is offered");
  }
  const std::string robot = config.robot_name.empty() ? "no robot" : "robot " + config.robot_name;
  ROS_INFO("world %s (%s), %s, physics step %g s, real-time factor %g%s", world.name.c_str(),
           config.world_file.c_str(), robot.c_str(), sim_config.physics_step_s,
           config.real_time_factor, config.start_paused ? ", paused" : "");
  // Sim time runs from the first step on, as a Gazebo world's time runs from when the
  // world starts: the wall time spent building the simulation is not caught up.
  pacer_.restart(sim_->timeS());
  runner_->publishClock();
}

void SimulatorNode::spinOnce(ros::CallbackQueue& callbacks) {
  if (runner_->paused()) {
    callbacks.callAvailable(ros::WallDuration(0.01));
    runner_->publishClock();
    pacer_.restart(sim_->timeS());
  } else {
    callbacks.callAvailable();
    runner_->step(pacer_.stepsDue(sim_->timeS(), sim_->physicsStepS(), runner_->roundSteps()));
    pacer_.waitUntil(sim_->timeS());
  }
  status_->maybeReport();
  updateMarkers();
  if (world_markers_) world_markers_->update();
}

void SimulatorNode::updateMarkers() {
  if (markers_param_.empty()) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_markers_check_ < std::chrono::milliseconds(200)) return;
  last_markers_check_ = now;
  bool wanted = false;
  // Cached: the master tells the node when the parameter changes.
  ros::param::getCached(markers_param_, wanted);
  if (wanted && !world_markers_) {
    world_markers_ = std::make_unique<WorldMarkersIo>(*sim_, gazebo_nh_);
    for (const std::string& model : world_models_) world_markers_->track(model);
  } else if (!wanted && world_markers_) {
    world_markers_.reset();
  }
}

}  // namespace bullet_sim_node
