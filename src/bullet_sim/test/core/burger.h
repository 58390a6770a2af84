#ifndef BULLET_SIM_TEST_BURGER_H
#define BULLET_SIM_TEST_BURGER_H

#include <string>

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/simulation.h"

namespace bullet_sim_test {

/// The workspace's Burger URDF (with the flag), expanded by the workspace's
/// xacro command; cached after the first call.
const std::string& burgerUrdf();
/// The parsed Burger.
bullet_sim::RobotSpec burgerSpec();
/// An empty world: a ground plane only.
bullet_sim::WorldSpec flatWorld();
/// The round-track world file of turtlebot3_gazebo.
std::string roundTrackPath();

/// Heading (rad) of an orientation: its yaw about the world's z.
double yawOf(const Eigen::Quaterniond& q);
/// Steps `sim` for `seconds` (1 ms steps) and returns how far `robot` turned, accumulated
/// step by step, so that turns beyond pi are measured.
double turnFor(bullet_sim::Simulation* sim, const std::string& robot, double seconds);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_BURGER_H
