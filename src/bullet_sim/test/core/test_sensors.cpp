// Sensor tests: lidar against the wall table, IMU, sensor scheduling.
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "round_track.h"

using namespace bullet_sim;

namespace {

constexpr double kSpawnYaw = 1.5675;
// base_footprint -> base_scan in the Burger description: base_joint z 0.010,
// scan_joint x -0.032 z 0.172.
constexpr double kScanOffsetX = -0.032;

void run(Simulation* sim, int steps) {
  for (int i = 0; i < steps; ++i) sim->step();
}

class BurgerOnRoundTrack : public ::testing::Test {
 protected:
  BurgerOnRoundTrack() : sim_(loadWorldFile(bullet_sim_test::roundTrackPath()), SimConfig()) {
    Pose3 spawn;
    spawn.orientation = Eigen::AngleAxisd(kSpawnYaw, Eigen::Vector3d::UnitZ());
    sim_.spawnRobot("burger", bullet_sim_test::burgerSpec(), spawn);
  }
  /// Expected range of scan ray i from the wall table, at the spawn pose.
  double expectedRange(const LaserScanData& scan, int i) const {
    const Eigen::Vector2d origin(kScanOffsetX * std::cos(kSpawnYaw), kScanOffsetX * std::sin(kSpawnYaw));
    return bullet_sim_test::wallDistance(origin, kSpawnYaw + scan.angle_min + i * scan.angle_increment,
                                         scan.range_max);
  }
  Simulation sim_;
};

}  // namespace

TEST_F(BurgerOnRoundTrack, LidarRangesToTheLaneWallsMatchTheWallTable) {
  run(&sim_, 200);
  const LaserScanData scan = sim_.readRay("burger", 0);
  ASSERT_EQ(scan.ranges.size(), 360u);
  EXPECT_EQ(scan.frame_id, "base_scan");
  EXPECT_NEAR(scan.angle_increment, 6.28319 / 359, 1e-12);
  // Left (+90 deg) and right (-90 deg = 270 deg): the lane's two walls.
  for (int centre : {90, 270}) {
    for (int i = centre - 10; i <= centre + 10; ++i) {
      const double expected = expectedRange(scan, i);
      ASSERT_TRUE(std::isfinite(expected)) << "ray " << i;
      EXPECT_NEAR(scan.ranges[i], expected, 0.04) << "ray " << i;
    }
  }
  EXPECT_NEAR(scan.ranges[90], 0.80, 0.04);   // west wall, 0.8 m to the left
  EXPECT_NEAR(scan.ranges[270], 0.51, 0.04);  // inner wall, 0.5 m to the right
}

TEST_F(BurgerOnRoundTrack, WholeScanAgreesWithTheWallTable) {
  run(&sim_, 200);
  const LaserScanData scan = sim_.readRay("burger", 0);
  int compared = 0, within = 0, inf_agree = 0, inf_expected = 0;
  for (int i = 1; i + 1 < 360; ++i) {
    const double e = expectedRange(scan, i);
    if (!std::isfinite(e)) {
      ++inf_expected;
      if (std::isinf(scan.ranges[i])) ++inf_agree;
      continue;
    }
    // Skip rays at a wall's end, where a small heading error jumps walls.
    if (std::fabs(expectedRange(scan, i - 1) - e) > 0.1 || std::fabs(expectedRange(scan, i + 1) - e) > 0.1) {
      continue;
    }
    ++compared;
    if (std::fabs(scan.ranges[i] - e) < 0.04) ++within;
  }
  EXPECT_GT(compared, 200);
  EXPECT_GE(within, compared * 99 / 100);
  EXPECT_GE(inf_agree, inf_expected * 95 / 100);
}

TEST(Lidar, NothingInRangeReadsInfinityAndOwnPolesAreNotSeen) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  run(&sim, 100);
  const LaserScanData scan = sim.readRay("burger", 0);
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    EXPECT_TRUE(std::isinf(scan.ranges[i])) << "ray " << i << " = " << scan.ranges[i];
  }
}

TEST_F(BurgerOnRoundTrack, ImuReadsGravityUpwardsAtRest) {
  run(&sim_, 1000);
  sim_.readImu("burger", 0);
  run(&sim_, 5);
  const ImuData imu = sim_.readImu("burger", 0);
  EXPECT_EQ(imu.frame_id, "imu_link");
  EXPECT_NEAR(imu.linear_acceleration.z(), 9.8, 0.05);
  // The Burger rests tilted back onto its caster (~1 degree), so gravity shows
  // a little on the IMU's x: in the world frame it is straight up.
  const Eigen::Vector3d accel_world = imu.orientation * imu.linear_acceleration;
  EXPECT_NEAR(accel_world.x(), 0, 0.01);
  EXPECT_NEAR(accel_world.y(), 0, 0.01);
  EXPECT_NEAR(accel_world.z(), 9.8, 0.01);
  EXPECT_NEAR(imu.angular_velocity.norm(), 0, 0.01);
  const double yaw = 2 * std::atan2(imu.orientation.z(), imu.orientation.w());
  EXPECT_NEAR(yaw, kSpawnYaw, 0.01);
}

TEST_F(BurgerOnRoundTrack, ImuYawRateMatchesTheTurnCommand) {
  sim_.setCmdVel("burger", 0, 1.0);
  run(&sim_, 1500);
  const ImuData imu = sim_.readImu("burger", 0);
  EXPECT_NEAR(imu.angular_velocity.z(), 1.0, 0.03);
}

TEST_F(BurgerOnRoundTrack, StepReportsEachSensorAtItsRate) {
  std::map<SensorKind, int> count;
  for (int i = 0; i < 1000; ++i) {
    for (const DueSensor& due : sim_.step()) {
      EXPECT_EQ(due.robot, "burger");
      ++count[due.kind];
    }
  }
  EXPECT_EQ(count[SensorKind::Ray], 5);
  EXPECT_EQ(count[SensorKind::Imu], 200);
  EXPECT_EQ(count[SensorKind::Camera], 30);
  EXPECT_EQ(count[SensorKind::Odometry], 30);
  EXPECT_EQ(count[SensorKind::JointStates], 30);
}

TEST(Lidar, SeesAnotherRobot) {
  // A panel robot (0.1 m deep, 0.6 m wide, 0.4 m tall) stands with its centre 1 m ahead of
  // the Burger: the lidar (0.032 m behind the Burger's centre) reads 1 - 0.05 + 0.032 m.
  // (Another Burger's lidar housing, 3 cm tall, is only met up close: the Burger rests
  // 1 degree nose-up on its caster, so its scan plane rises 1.6 cm per metre.)
  const char* panel = R"(<robot name="panel"><link name="panel">
    <inertial><origin xyz="0 0 0.2"/><mass value="5"/>
      <inertia ixx="0.2" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial>
    <collision><origin xyz="0 0 0.2"/><geometry><box size="0.1 0.6 0.4"/></geometry></collision>
  </link></robot>)";
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  Pose3 ahead;
  ahead.position.x() = 1.0;
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  sim.spawnRobot("panel", parseRobot(panel, "panel.urdf"), ahead);
  run(&sim, 300);
  EXPECT_NEAR(sim.readRay("burger", 0).ranges[0], 1.0 - 0.05 + 0.032, 0.04);
  sim.deleteRobot("panel");
  run(&sim, 10);
  EXPECT_TRUE(std::isinf(sim.readRay("burger", 0).ranges[0]));
}

namespace {

/// The world steps (1-based, 1 kHz) at which each kind of the robot's readings fell due.
std::map<SensorKind, std::vector<int>> dueSteps(Simulation* sim, int from_step, int to_step) {
  std::map<SensorKind, std::vector<int>> steps;
  for (int k = from_step; k <= to_step; ++k) {
    for (const DueSensor& due : sim->step()) steps[due.kind].push_back(k);
  }
  return steps;
}

}  // namespace

TEST(SensorPhase, ARobotInTheWorldFromTheStartMeasuresAfterOnePeriod) {
  // Gazebo's sensors count their last update from world time 0: lidar (5 Hz) first at
  // 0.2 s, camera (30 Hz) first at the step where 1/30 s has passed (step 34).
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  auto steps = dueSteps(&sim, 1, 450);
  EXPECT_EQ(steps[SensorKind::Ray], (std::vector<int>{200, 400}));
  EXPECT_EQ(steps[SensorKind::Camera].front(), 34);
}

TEST(SensorPhase, ARobotSpawnedIntoARunningWorldMeasuresAtOnce) {
  // Spawned after 0.5 s of world time, more than a lidar period: the lidar and the camera
  // measure with the first step after the spawn (501), then every period from there; the
  // IMU plugin and the diff drive keep world-time phase (every 5 and 33.3 steps).
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  for (int k = 1; k <= 500; ++k) sim.step();
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  auto steps = dueSteps(&sim, 501, 950);
  EXPECT_EQ(steps[SensorKind::Ray], (std::vector<int>{501, 701, 901}));
  ASSERT_GE(steps[SensorKind::Camera].size(), 3u);
  EXPECT_EQ(steps[SensorKind::Camera][0], 501);
  EXPECT_EQ(steps[SensorKind::Camera][1], 534);  // 1/30 s = 33.3 steps after the first
  EXPECT_EQ(steps[SensorKind::Camera][2], 567);
  EXPECT_EQ(steps[SensorKind::Imu].front(), 505);
  EXPECT_EQ(steps[SensorKind::Odometry].front(), 534);  // 16/30 s = 533.3 ms
}

TEST(SensorPhase, ARobotSpawnedWithinTheFirstPeriodWaitsForItsEnd) {
  // Spawned at 0.05 s: the lidar's first period, counted from world time 0, ends at 0.2 s.
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  for (int k = 1; k <= 50; ++k) sim.step();
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  EXPECT_EQ(dueSteps(&sim, 51, 450)[SensorKind::Ray], (std::vector<int>{200, 400}));
}

TEST(SensorPhase, AResetWorldCountsFromZeroAgain) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  for (int k = 1; k <= 500; ++k) sim.step();
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  sim.step();
  sim.reset();
  EXPECT_EQ(dueSteps(&sim, 1, 450)[SensorKind::Ray], (std::vector<int>{200, 400}));
}

namespace {

/// A static SDF model (no inertial: none is needed) of one box `size` centred at `centre`.
std::string staticBox(const std::string& size, const std::string& centre) {
  return "<sdf version='1.6'><model name='wall'><static>true</static><pose>" + centre +
         " 0 0 0</pose><link name='link'><collision name='c'><geometry><box><size>" + size +
         "</size></box></geometry></collision><visual name='v'><geometry><box><size>" + size +
         "</size></box></geometry></visual></link></model></sdf>";
}

}  // namespace

TEST(StaticModels, ASpawnedStaticBoxIsSeenByTheLidarStopsTheRobotAndGoesWhenDeleted) {
  // A static box 0.2 m deep, 0.6 m wide, 0.5 m tall, centred 1 m ahead of the Burger: its
  // front face is at x 0.9, which the lidar (0.032 m behind the Burger's centre) reads at
  // 0.9 + 0.032 m. It has no inertial and floats at z 0.25 (static models do not fall).
  const RobotSpec spec = parseSdfModelString(staticBox("0.2 0.6 0.5", "1 0 0.25"),
                                             "spawn_sdf_model", UriResolver(ResourcePaths{}));
  EXPECT_TRUE(spec.is_static);
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  Pose3 at;
  at.position = Eigen::Vector3d(1, 0, 0.25);
  sim.spawnRobot("wall", spec, at);
  run(&sim, 300);
  EXPECT_NEAR(sim.readRay("burger", 0).ranges[0], 0.9 + 0.032, 0.01);
  EXPECT_TRUE(sim.modelPose("wall").position.isApprox(at.position, 1e-12));
  // Driven at it at 0.2 m/s for 8 s (1.6 m), the Burger stops at the face: its chassis
  // (the front of its 0.14 m base plate, 0.038 m ahead of its centre) against x 0.9, and the
  // wall does not budge.
  sim.setCmdVel("burger", 0.2, 0);
  run(&sim, 8000);
  const double x = sim.modelPose("burger").position.x();
  EXPECT_LT(x, 0.9 - 0.03);
  EXPECT_GT(x, 0.9 - 0.12);
  EXPECT_TRUE(sim.modelPose("wall").position.isApprox(at.position, 1e-12));
  EXPECT_NEAR(sim.modelPose("wall").orientation.angularDistance(Eigen::Quaterniond::Identity()),
              0, 1e-12);
  sim.setCmdVel("burger", 0, 0);
  EXPECT_TRUE(sim.deleteRobot("wall"));
  run(&sim, 300);
  EXPECT_TRUE(std::isinf(sim.readRay("burger", 0).ranges[0]));
}

TEST(StaticModels, AStaticModelWithABadBoxSizeIsRefusedNamingTheElement) {
  try {
    parseSdfModelString(staticBox("0.2 nan 0.5", "1 0 0.25"), "spawn_sdf_model",
                        UriResolver(ResourcePaths{}));
    FAIL() << "a box of size '0.2 nan 0.5' was accepted";
  } catch (const LoadError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("size"), std::string::npos) << what;
    EXPECT_NE(what.find("nan"), std::string::npos) << what;
  }
}
