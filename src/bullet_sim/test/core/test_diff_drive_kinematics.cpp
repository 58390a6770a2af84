// The diff drive's kinematics on the Burger's figures (wheel separation 0.160 m, radius
// 0.033 m): wheel speeds for a command, the command back from wheel speeds, and the encoder
// odometry's pose update on arcs whose end points are known in closed form.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/diff_drive_kinematics.h"

using bullet_sim::advancePose;
using bullet_sim::DiffDriveKinematics;

namespace {

const DiffDriveKinematics kBurger{0.160, 0.033};

/// The pose after `seconds` at constant forward and turn rates, in steps of `dt_s`.
Eigen::Vector3d drive(double linear_mps, double angular_radps, double seconds, double dt_s) {
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();
  const long steps = std::lround(seconds / dt_s);
  for (long i = 0; i < steps; ++i) {
    pose = advancePose(pose, linear_mps * dt_s, angular_radps * dt_s);
  }
  return pose;
}

}  // namespace

TEST(DiffDriveKinematics, WheelSpeedsForStraightTurningAndArcCommands) {
  // Straight at the Burger's top speed: both wheels 0.22 / 0.033 = 6.6667 rad/s.
  Eigen::Vector2d w = kBurger.wheelVelocities(0.22, 0);
  EXPECT_NEAR(w[0], 6.666667, 1e-6);
  EXPECT_NEAR(w[1], 6.666667, 1e-6);
  // On the spot at its top turn rate: rims at -+2.84 * 0.08 = -+0.2272 m/s, so -+6.8848 rad/s.
  w = kBurger.wheelVelocities(0, 2.84);
  EXPECT_NEAR(w[0], -6.884848, 1e-6);
  EXPECT_NEAR(w[1], 6.884848, 1e-6);
  // v 0.1, w 0.5: (0.1 - 0.04) / 0.033 = 1.81818 and (0.1 + 0.04) / 0.033 = 4.24242.
  w = kBurger.wheelVelocities(0.1, 0.5);
  EXPECT_NEAR(w[0], 1.818182, 1e-6);
  EXPECT_NEAR(w[1], 4.242424, 1e-6);
  // Backwards, turning clockwise: the left rim at -0.1 + 0.04 = -0.06 m/s, the right at
  // -0.1 - 0.04 = -0.14 m/s.
  w = kBurger.wheelVelocities(-0.1, -0.5);
  EXPECT_NEAR(w[0], -1.818182, 1e-6);
  EXPECT_NEAR(w[1], -4.242424, 1e-6);
}

TEST(DiffDriveKinematics, BaseVelocitiesUndoWheelVelocities) {
  // Left 2 rad/s, right 4 rad/s: v = 0.033 * 3 = 0.099 m/s, w = 0.033 * 2 / 0.16 = 0.4125.
  const Eigen::Vector2d base = kBurger.baseVelocities(2, 4);
  EXPECT_NEAR(base[0], 0.099, 1e-12);
  EXPECT_NEAR(base[1], 0.4125, 1e-12);
  for (const auto& vw : {Eigen::Vector2d(0.22, 0), Eigen::Vector2d(0, -2.84),
                         Eigen::Vector2d(0.15, 0.5), Eigen::Vector2d(-0.05, 1.2)}) {
    const Eigen::Vector2d wheels = kBurger.wheelVelocities(vw[0], vw[1]);
    EXPECT_TRUE(kBurger.baseVelocities(wheels[0], wheels[1]).isApprox(vw, 1e-12))
        << vw.transpose();
  }
}

TEST(DiffDriveKinematics, EncoderPoseFollowsArcs) {
  // A quarter circle of radius v / w = 0.5 m from the origin heading +x ends at (0.5, 0.5)
  // heading pi/2. Each step moves the arc length along the chord, which scales the path
  // by (t/2) / sin(t/2) = 1 + t^2/24 for a step's turn t = 0.4 mrad: 6e-9, a few nm here.
  const double v = 0.2, w = 0.4, quarter_s = (M_PI / 2) / w;
  const Eigen::Vector3d quarter = drive(v, w, quarter_s, quarter_s / 4000);
  EXPECT_NEAR(quarter.x(), 0.5, 1e-8);
  EXPECT_NEAR(quarter.y(), 0.5, 1e-8);
  EXPECT_NEAR(quarter.z(), M_PI / 2, 1e-12);
  // A whole turn comes back to the start however coarse the steps: they are the sides of
  // a regular polygon. In 8 steps of 45 degrees that polygon is (t/2) / sin(t/2) = 2.6 %
  // larger than the inscribed one, but it still closes.
  const Eigen::Vector3d turn = drive(v, w, 2 * M_PI / w, 2 * M_PI / w / 8);
  EXPECT_NEAR(turn.x(), 0, 1e-12);
  EXPECT_NEAR(turn.y(), 0, 1e-12);
  EXPECT_NEAR(turn.z(), 2 * M_PI, 1e-12);
  // Straight: 0.22 m/s for 2 s heading 0 is 0.44 m along x.
  const Eigen::Vector3d straight = drive(0.22, 0, 2.0, 0.001);
  EXPECT_NEAR(straight.x(), 0.44, 1e-12);
  EXPECT_EQ(straight.y(), 0);
}
