#ifndef BULLET_SIM_TEST_BURGER_H
#define BULLET_SIM_TEST_BURGER_H

#include <string>

#include "bullet_sim/robot_spec.h"
#include "bullet_sim/world_spec.h"

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

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_BURGER_H
