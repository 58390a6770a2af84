// bullet_sim_node: runs the Bullet simulation of a world, publishing /clock and the
// robots' sensors and offering gazebo_ros's services and topics under /gazebo. A robot
// is spawned from robot_description at start only when ~robot_name is set; others arrive
// through /gazebo/spawn_urdf_model.
#include "config.h"
#include "link_joint_services.h"
#include "model_services.h"
#include "pacer.h"
#include "physics_services.h"
#include "sim_runner.h"
#include "status_reporter.h"
#include "world_markers_io.h"

#include <bullet_sim/errors.h>
#include <bullet_sim/robot_spec.h>
#include <bullet_sim/simulation.h>
#include <bullet_sim/world_spec.h>

#include <ros/callback_queue.h>
#include <ros/ros.h>

namespace {

using bullet_sim_node::Config;

void logWarnings(const std::string& source, const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) ROS_WARN("%s: %s", source.c_str(), warning.c_str());
}

void spawnStartRobot(const Config& config, bullet_sim_node::SimRunner* runner) {
  const bullet_sim::RobotSpec robot =
      bullet_sim::parseRobot(config.robot_description, "robot_description");
  logWarnings("robot_description", robot.warnings);
  bullet_sim::Pose3 pose;
  pose.position = {config.spawn_x_m, config.spawn_y_m, 0.0};
  pose.orientation = Eigen::AngleAxisd(config.spawn_yaw_rad, Eigen::Vector3d::UnitZ());
  runner->spawn(config.robot_name, robot, pose, "");
}

int run(const Config& config, ros::NodeHandle& nh) {
  const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(config.world_file);
  logWarnings(config.world_file, world.warnings);
  bullet_sim::SimConfig sim_config;
  sim_config.physics_step_s =
      config.physics_step_s > 0 ? config.physics_step_s : world.max_step_size_s;
  sim_config.seed = static_cast<uint64_t>(config.seed);
  sim_config.cmd_vel_timeout_s = config.cmd_vel_timeout_s;
  bullet_sim::Simulation sim(world, sim_config);
  const ros::NodeHandle gazebo_nh("/gazebo");
  bullet_sim_node::SimRunner runner(sim, nh, gazebo_nh, config.start_paused,
                                    config.model_states_rate_hz);
  runner.logSimulationWarnings();  // how the world's movable models were built
  bullet_sim_node::releaseParserMemory();
  if (!config.robot_name.empty()) spawnStartRobot(config, &runner);
  bullet_sim_node::Pacer pacer(config.real_time_factor);
  bullet_sim_node::PhysicsServices physics_services(runner, pacer, gazebo_nh);
  bullet_sim_node::ModelServices model_services(runner, gazebo_nh);
  bullet_sim_node::LinkJointServices link_joint_services(runner, gazebo_nh);
  bullet_sim_node::StatusReporter status(sim, config.status_period_s);
  bullet_sim_node::WorldMarkersIo world_markers(sim, gazebo_nh);
  for (const bullet_sim::WorldModel& model : world.models) world_markers.track(model.name);
  const std::string robot = config.robot_name.empty() ? "no robot" : "robot " + config.robot_name;
  ROS_INFO("world %s (%s), %s, physics step %g s, real-time factor %g%s", world.name.c_str(),
           config.world_file.c_str(), robot.c_str(), sim_config.physics_step_s, config.real_time_factor,
           config.start_paused ? ", paused" : "");
  runner.publishClock();

  ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
  while (ros::ok()) {
    if (runner.paused()) {
      callbacks.callAvailable(ros::WallDuration(0.01));
      runner.publishClock();
      pacer.restart(sim.timeS());
    } else {
      callbacks.callAvailable();
      runner.step();
      pacer.waitUntil(sim.timeS());
    }
    status.maybeReport();
    world_markers.update();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "bullet_sim");
  ros::NodeHandle nh;
  try {
    const Config config = bullet_sim_node::readConfig(nh, ros::NodeHandle("~"));
    return run(config, nh);
  } catch (const bullet_sim_node::ConfigError& error) {
    ROS_FATAL("%s", error.what());
  } catch (const bullet_sim::LoadError& error) {
    ROS_FATAL("%s", error.what());
  } catch (const std::exception& error) {
    ROS_FATAL("simulation failed: %s", error.what());
  }
  return 1;
}
