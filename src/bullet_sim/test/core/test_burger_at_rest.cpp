// A Burger at rest sits on its wheels and its caster, nose up, and its scan plane rises
// with it: what another Burger's lidar housing straight ahead looks like to its lidar,
// derived from the description's numbers (turtlebot3_burger.urdf.xacro):
//   base_footprint -> base_link z 0.010; wheel joints z 0.023, wheel radius 0.033;
//   caster_back_joint x -0.081 z -0.004, rpy -1.57 0 0, its box 0.030 x 0.009 x 0.020
//   (the 0.009 side vertical once turned); scan_joint x -0.032 z 0.172; the housing's
//   collision cylinder radius 0.055 length 0.0315 at x +0.015 z -0.0065 from base_scan;
//   the lidar's range resolution 0.015 m.
#include <gtest/gtest.h>

#include <cmath>

#include "bullet_sim/simulation.h"
#include "burger.h"

namespace {

using namespace bullet_sim;

constexpr double kWheelBottom = 0.010 + 0.023 - 0.033;     // above base_footprint: 0
constexpr double kCasterBottom = 0.010 - 0.004 - 0.009 / 2;  // 0.0015: above the ground
constexpr double kCasterX = -0.081;
constexpr double kScanX = -0.032, kScanZ = 0.010 + 0.172;
constexpr double kHousingX = kScanX + 0.015, kHousingRadius = 0.055;
constexpr double kHousingTop = kScanZ - 0.0065 + 0.0315 / 2;
constexpr double kResolution = 0.015;

/// A point (x, z) of a robot's base_footprint, pitched nose up by `pitch` about the wheels'
/// contact line, in a frame level with the ground (x forward).
Eigen::Vector2d pitched(double x, double z, double pitch) {
  return {x * std::cos(pitch) - z * std::sin(pitch), x * std::sin(pitch) + z * std::cos(pitch)};
}

double noseUpPitch(const Pose3& pose) {
  const Eigen::Vector3d forward = pose.orientation * Eigen::Vector3d::UnitX();
  return std::atan2(forward.z(), std::hypot(forward.x(), forward.y()));
}

/// "looker" at the origin and "seen" `ahead` metres in front of it, both facing +x, settled.
struct TwoBurgersInLine {
  explicit TwoBurgersInLine(double ahead) : sim(bullet_sim_test::flatWorld(), SimConfig()) {
    Pose3 seen;
    seen.position.x() = ahead;
    sim.spawnRobot("looker", bullet_sim_test::burgerSpec(), Pose3());
    sim.spawnRobot("seen", bullet_sim_test::burgerSpec(), seen);
    while (sim.timeS() < 1.0) sim.step();
  }
  Simulation sim;
};

TEST(BurgerAtRest, SitsNoseUpOnItsCaster) {
  // Its mass is behind the wheels (the lidar, the flag), so it tips back until the caster,
  // whose bottom is 1.5 mm above the wheels' contact line, touches the ground.
  ASSERT_GT(kCasterBottom - kWheelBottom, 0.0);
  const double geometric = std::atan2(kCasterBottom - kWheelBottom, -kCasterX);  // 1.06 deg
  TwoBurgersInLine burgers(2.0);
  const double pitch = noseUpPitch(burgers.sim.modelPose("looker"));
  // Contact penetration of wheels and caster takes up to a quarter of the 1.5 mm.
  EXPECT_GT(pitch, 0.75 * geometric);
  EXPECT_LE(pitch, geometric + 1e-3);
}

TEST(BurgerAtRest, LidarSeesAnotherBurgersHousingOnlyWhileTheRisingScanPlaneMeetsIt) {
  const double pitch = noseUpPitch(TwoBurgersInLine(2.0).sim.modelPose("looker"));
  // The ray straight ahead leaves the scanner and climbs at the pitch; the seen robot's
  // housing faces it with its back, whose top edge is pitched as much.
  const Eigen::Vector2d scanner = pitched(kScanX, kScanZ, pitch);
  const Eigen::Vector2d edge = pitched(kHousingX - kHousingRadius, kHousingTop, pitch);
  // The ray passes the back's top edge when ahead + edge.x() - scanner.x() reaches:
  const double reach = (edge.y() - scanner.y()) / std::tan(pitch);
  const double last_seen_ahead = reach - edge.x() + scanner.x();  // about 0.6 m
  ASSERT_GT(last_seen_ahead, 0.4);
  ASSERT_LT(last_seen_ahead, 0.8);
  for (double ahead : {last_seen_ahead - 0.1, last_seen_ahead - 0.2}) {
    TwoBurgersInLine burgers(ahead);
    const double to_back = ahead + edge.x() - scanner.x();  // along the ray, to the housing
    EXPECT_NEAR(burgers.sim.readRay("looker", 0).ranges[0], to_back, kResolution + 0.002)
        << ahead << " m ahead";
  }
  for (double ahead : {last_seen_ahead + 0.1, 1.0}) {
    TwoBurgersInLine burgers(ahead);
    EXPECT_TRUE(std::isinf(burgers.sim.readRay("looker", 0).ranges[0]))
        << ahead << " m ahead: the scan plane passes over the housing";
  }
}

}  // namespace
