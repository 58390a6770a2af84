// Simulation::castRays: segments through a world's static box and a spawned robot's box,
// distances worked out from their sizes and poses.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/simulation.h"

using namespace bullet_sim;

namespace {

/// A static wall 0.1 m thick whose near face is at x = 1.95, 2 m wide in y, 1 m high.
const char* kWallWorld = R"(<sdf version="1.6"><world name="w">
  <model name="wall"><static>true</static><pose>2 0 0.5 0 0 0</pose>
    <link name="l"><collision name="c"><geometry><box><size>0.1 2 1</size></box></geometry>
    </collision></link></model></world></sdf>)";

/// A 0.2 m cube, its centre at the model frame.
const char* kCubeUrdf = R"(<robot name="cube">
  <link name="body">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
</robot>)";

class CastRays : public ::testing::Test {
 protected:
  CastRays() : sim_(loadWorldString(kWallWorld, "wall world"), config()) {}
  static SimConfig config() {
    SimConfig c;
    c.threads = 1;
    return c;
  }
  Simulation sim_;
};

TEST_F(CastRays, DistanceToTheWallsNearFace) {
  const std::vector<double> d =
      sim_.castRays({{0, 0, 0.5}, {0, 0.5, 0.2}, {1.0, -0.9, 0.9}},
                    {{5, 0, 0.5}, {5, 0.5, 0.2}, {3.0, -0.9, 0.9}});
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR(d[0], 1.95, 1e-6);
  EXPECT_NEAR(d[1], 1.95, 1e-6);
  EXPECT_NEAR(d[2], 0.95, 1e-6);
}

TEST_F(CastRays, SegmentsThatHitNothingAreInfinite) {
  const double inf = std::numeric_limits<double>::infinity();
  // short of the wall; beside it (|y| > 1); above it (z > 1); of length zero
  const std::vector<double> d = sim_.castRays(
      {{0, 0, 0.5}, {0, 1.2, 0.5}, {0, 0, 1.2}, {1, 1, 1}},
      {{1.9, 0, 0.5}, {5, 1.2, 0.5}, {5, 0, 1.2}, {1, 1, 1}});
  for (double x : d) EXPECT_EQ(x, inf);
}

TEST_F(CastRays, SeesRobotsWhereTheyAreNow) {
  Pose3 at;
  at.position = {1, 0, 0.5};
  sim_.spawnRobot("cube", parseRobot(kCubeUrdf, "cube"), at);
  EXPECT_NEAR(sim_.castRays({{0, 0, 0.5}}, {{5, 0, 0.5}})[0], 0.9, 1e-6);
  // moved out of the way (no gravity acts on a pose set between steps): the wall again
  at.position = {1, 3, 0.5};
  sim_.setModelState("cube", at, Twist3{});
  EXPECT_NEAR(sim_.castRays({{0, 0, 0.5}}, {{5, 0, 0.5}})[0], 1.95, 1e-6);
  EXPECT_NEAR(sim_.castRays({{1, 0, 0.5}}, {{1, 5, 0.5}})[0], 2.9, 1e-6);
}

TEST_F(CastRays, AnIgnoredRobotIsPassedThrough) {
  Pose3 at;
  at.position = {1, 0, 0.5};
  sim_.spawnRobot("cube", parseRobot(kCubeUrdf, "cube"), at);
  // from the cube's centre: its own faces are not hit, the wall is
  EXPECT_NEAR(sim_.castRays({{1, 0, 0.5}}, {{5, 0, 0.5}}, "cube")[0], 0.95, 1e-6);
  EXPECT_NEAR(sim_.castRays({{0, 0, 0.5}}, {{5, 0, 0.5}}, "cube")[0], 1.95, 1e-6);
  EXPECT_THROW(sim_.castRays({{0, 0, 0.5}}, {{5, 0, 0.5}}, "sphere"), std::out_of_range);
}

TEST_F(CastRays, BadInputIsRefused) {
  EXPECT_THROW(sim_.castRays({{0, 0, 0}}, {}), std::invalid_argument);
  EXPECT_THROW(sim_.castRays({{0, 0, std::nan("")}}, {{1, 0, 0}}), std::invalid_argument);
  EXPECT_TRUE(sim_.castRays({}, {}).empty());
}

}  // namespace
