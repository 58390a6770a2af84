// The node's status line: poses, and a model that tipped over or went into a wall said so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <bullet_sim/simulation.h>

#include "../core/burger.h"
#include "runner/status_reporter.h"

namespace {

using bullet_sim::Pose3;
using bullet_sim::Simulation;

/// The Burger on the round track, stepped `steps` times from `pose`.
std::string lineAfter(const Pose3& pose, int steps, bool* trouble) {
  static const bullet_sim::WorldSpec world =
      bullet_sim::loadWorldFile(bullet_sim_test::roundTrackPath());
  Simulation sim(world, bullet_sim::SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), pose);
  for (int i = 0; i < steps; ++i) sim.step();
  return bullet_sim_node::statusLine(sim, 1.0, trouble);
}

TEST(StatusLine, AnUprightFreeRobotIsReportedAtItsPose) {
  Pose3 pose;
  pose.orientation = Eigen::AngleAxisd(1.5675, Eigen::Vector3d::UnitZ());
  bool trouble = true;
  const std::string line = lineAfter(pose, 100, &trouble);
  EXPECT_FALSE(trouble) << line;
  const size_t at = line.find("sim time 0.100 s, real-time factor 1.00, burger at x ");
  ASSERT_NE(at, std::string::npos) << line;
  double x = 1, y = 1, yaw = 0;
  ASSERT_EQ(std::sscanf(line.c_str() + at, "sim time 0.100 s, real-time factor 1.00, burger at "
                                           "x %lf y %lf yaw %lf", &x, &y, &yaw), 3) << line;
  EXPECT_NEAR(x, 0.0, 0.001);
  EXPECT_NEAR(y, 0.0, 0.001);
  EXPECT_NEAR(yaw, 1.5675, 0.002);
}

TEST(StatusLine, ARobotOnItsSideIsTippedOver) {
  // Lying on its side (rolled 90 degrees) 0.1 m above the ground; it falls and stays down.
  Pose3 pose;
  pose.position = {0.0, 0.0, 0.1};
  pose.orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX());
  bool trouble = false;
  const std::string line = lineAfter(pose, 1000, &trouble);
  EXPECT_TRUE(trouble);
  EXPECT_NE(line.find("TIPPED OVER (tilted 9"), std::string::npos) << line;  // about 90 deg
  EXPECT_EQ(line.find("STUCK IN A WALL"), std::string::npos) << line;
}

TEST(StatusLine, ARobotPlacedAcrossAWallIsStuckInIt) {
  // The west wall's centre line is x = -0.80941 (0.015 m thick, along y); the Burger's body
  // spans x -0.102..0.038 about base_footprint when facing +x: put the wall through it.
  Pose3 pose;
  pose.position = {-0.80941 + 0.03, 0.0, 0.0};
  bool trouble = false;
  const std::string line = lineAfter(pose, 1, &trouble);
  EXPECT_TRUE(trouble);
  EXPECT_NE(line.find("STUCK IN A WALL ("), std::string::npos) << line;
}

}  // namespace
