// The panel's and tool's logic: real-time factor measurement, Gazebo's max_update_rate,
// the panel's words, and picked poses taken from RViz's fixed frame to the world.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "bullet_sim_rviz/physics_rate.h"
#include "bullet_sim_rviz/planar_pose.h"
#include "bullet_sim_rviz/rtf_estimator.h"
#include "bullet_sim_rviz/sim_snapshot.h"

using namespace bullet_sim_rviz;

TEST(RtfEstimator, HalfRealTimeOverTheWindow) {
  RtfEstimator rtf(2.0);
  // /clock every 10 ms of wall time, 5 ms of sim time each.
  for (int i = 0; i <= 300; ++i) rtf.addSample(100.0 + 0.01 * i, 0.005 * i);
  ASSERT_TRUE(rtf.factor(103.0).has_value());
  EXPECT_NEAR(*rtf.factor(103.0), 0.5, 1e-9);
}

TEST(RtfEstimator, FollowsAChangeOfPaceWithinOneWindow) {
  RtfEstimator rtf(1.0);
  double sim = 0;
  for (int i = 0; i < 100; ++i) rtf.addSample(0.01 * i, sim += 0.01);   // real time
  for (int i = 100; i < 250; ++i) rtf.addSample(0.01 * i, sim += 0.1);  // 10x
  EXPECT_NEAR(*rtf.factor(2.49), 10.0, 1e-6);
}

TEST(RtfEstimator, PausedIsZeroAndSilenceIsUnknown) {
  RtfEstimator rtf(1.0);
  for (int i = 0; i < 100; ++i) rtf.addSample(0.01 * i, 42.0);  // a paused simulator's /clock
  EXPECT_DOUBLE_EQ(*rtf.factor(1.0), 0.0);
  // No /clock for longer than the window: no simulator, no factor.
  EXPECT_FALSE(rtf.factor(2.5).has_value());
}

TEST(RtfEstimator, StalledWhileTheClockStandsStill) {
  RtfEstimator rtf(2.0);
  for (int i = 0; i <= 10; ++i) rtf.addSample(0.1 * i, 0.1 * i);  // running until 1.0 s
  EXPECT_FALSE(rtf.stalled(1.0, 0.3));
  for (int i = 11; i <= 15; ++i) rtf.addSample(0.1 * i, 1.0);  // paused at 1.0 s of wall
  EXPECT_TRUE(rtf.stalled(1.5, 0.3));
  EXPECT_FALSE(rtf.stalled(1.2, 0.3));   // only 0.2 s still so far
  EXPECT_FALSE(rtf.stalled(4.0, 0.3));   // no /clock for longer than the window: unknown
}

TEST(RtfEstimator, NeedsAQuarterWindowAndRestartsAfterAReset) {
  RtfEstimator rtf(2.0);
  rtf.addSample(0.0, 10.0);
  rtf.addSample(0.1, 10.1);
  EXPECT_FALSE(rtf.factor(0.1).has_value());  // 0.1 s of samples < 0.5 s
  for (int i = 2; i <= 10; ++i) rtf.addSample(0.1 * i, 10.0 + 0.1 * i);
  EXPECT_NEAR(*rtf.factor(1.0), 1.0, 1e-9);
  // reset_simulation: the clock jumps back to 0; the jump is not a negative factor.
  rtf.addSample(1.1, 0.0);
  EXPECT_FALSE(rtf.factor(1.1).has_value());
  for (int i = 1; i <= 10; ++i) rtf.addSample(1.1 + 0.1 * i, 0.2 * i);
  EXPECT_NEAR(*rtf.factor(2.1), 2.0, 1e-9);
  EXPECT_THROW(RtfEstimator(0.0), std::invalid_argument);
}

TEST(PhysicsRate, FactorIsRateTimesStep) {
  EXPECT_DOUBLE_EQ(maxUpdateRateFor(1.0, 0.001), 1000.0);
  EXPECT_DOUBLE_EQ(maxUpdateRateFor(2.5, 0.004), 625.0);
  EXPECT_DOUBLE_EQ(maxUpdateRateFor(0.0, 0.001), 0.0);  // as fast as possible
  EXPECT_DOUBLE_EQ(realTimeFactorOf(1000.0, 0.001), 1.0);
  EXPECT_DOUBLE_EQ(realTimeFactorOf(0.0, 0.001), 0.0);
}

TEST(PhysicsRate, BadValuesAreNamed) {
  try {
    maxUpdateRateFor(-1, 0.001);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "real-time factor -1.000000 must be >= 0 (0 = as fast as possible)");
  }
  try {
    realTimeFactorOf(1000, 0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "time_step 0.000000 must be > 0 s");
  }
  EXPECT_THROW(maxUpdateRateFor(NAN, 0.001), std::invalid_argument);
  EXPECT_THROW(realTimeFactorOf(-5, 0.001), std::invalid_argument);
}

TEST(SimSnapshot, HeadlineSaysWhenNoSimulatorRuns) {
  SimSnapshot s;
  EXPECT_EQ(headline(s), "No simulator running (no /gazebo/pause_physics service)");
  s.services_available = true;
  EXPECT_EQ(headline(s), "Simulator found, waiting for /clock");
  s.sim_time_s = 3.0;
  s.measured_rtf = 0.98;
  EXPECT_EQ(headline(s), "Simulation running");
  s.clock_stalled = true;  // no physics properties served: a still clock means paused
  EXPECT_EQ(headline(s), "Simulation paused");
  s.paused = false;  // what get_physics_properties says wins
  EXPECT_EQ(headline(s), "Simulation running");
  s.paused = true;
  s.measured_rtf = 1.0;
  EXPECT_TRUE(isPaused(s));
}

TEST(SimSnapshot, Texts) {
  EXPECT_EQ(simTimeText(std::nullopt), "-");
  EXPECT_EQ(simTimeText(12.3456), "12.346 s");
  EXPECT_EQ(rtfText(std::nullopt), "-");
  EXPECT_EQ(rtfText(0.984), "0.98");
  EXPECT_EQ(rtfText(118.6), "119");
}

TEST(PlanarPose, IdentityLeavesThePoseAlone) {
  const PlanarPose p = toWorld({1.5, -2.0, 0.3}, Eigen::Isometry3d::Identity());
  EXPECT_DOUBLE_EQ(p.x_m, 1.5);
  EXPECT_DOUBLE_EQ(p.y_m, -2.0);
  EXPECT_NEAR(p.yaw_rad, 0.3, 1e-12);
}

TEST(PlanarPose, ShiftedAndTurnedFixedFrame) {
  // The world's origin sits at (1, 2) of the fixed frame, turned +90 deg: the fixed point
  // (1, 3) is 1 m along the world's x axis, and a heading of 90 deg in the fixed frame is
  // 0 deg in the world.
  Eigen::Isometry3d T_fixed_world = Eigen::Isometry3d::Identity();
  T_fixed_world.translate(Eigen::Vector3d(1, 2, 0));
  T_fixed_world.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const PlanarPose p = toWorld({1.0, 3.0, M_PI / 2}, T_fixed_world);
  EXPECT_NEAR(p.x_m, 1.0, 1e-12);
  EXPECT_NEAR(p.y_m, 0.0, 1e-12);
  EXPECT_NEAR(p.yaw_rad, 0.0, 1e-12);
}
