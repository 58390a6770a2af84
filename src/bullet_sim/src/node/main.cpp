// bullet_sim_node: runs the Bullet simulation of a world, publishing /clock and the
// robots' sensors and offering gazebo_ros's services and topics under /gazebo. A robot
// is spawned from robot_description at start only when ~robot_name is set; others arrive
// through /gazebo/spawn_urdf_model. The bullet_sim/Simulator nodelet runs the same.
#include "config.h"
#include "gazebo_paths.h"
#include "simulator_node.h"

#include <bullet_sim/errors.h>

#include <ros/callback_queue.h>
#include <ros/ros.h>

int main(int argc, char** argv) {
  bullet_sim_node::collectExportedModelPaths();
  ros::init(argc, argv, "bullet_sim");
  ros::NodeHandle nh;
  try {
    const bullet_sim_node::Config config =
        bullet_sim_node::readConfig(nh, ros::NodeHandle("~"));
    const ros::NodeHandle gazebo_nh("/gazebo");
    bullet_sim_node::SimulatorNode simulator(config, nh, gazebo_nh);
    ros::CallbackQueue& callbacks = *ros::getGlobalCallbackQueue();
    while (ros::ok()) simulator.spinOnce(callbacks);
    return 0;
  } catch (const bullet_sim_node::ConfigError& error) {
    ROS_FATAL("%s", error.what());
  } catch (const bullet_sim::LoadError& error) {
    ROS_FATAL("%s", error.what());
  } catch (const std::exception& error) {
    ROS_FATAL("simulation failed: %s", error.what());
  }
  return 1;
}
