// libgazebo_ros_planar_move.so: the model is given the commanded planar velocity at every
// step. A 1 kg box (plugin_robots.h) floats in a world without gravity, where nothing but
// the plugin moves it, so its path is worked out by hand: with 1 ms steps each step moves
// it by the command turned by the yaw at the step's start.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "plugin_robots.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

constexpr double kStepS = 0.001;  // SimConfig's default physics step

std::string planarMove(const std::string& inside) {
  return "<gazebo><plugin name='move' filename='libgazebo_ros_planar_move.so'>" + inside +
         "</plugin></gazebo>";
}

/// The box at (1, 2, 1) turned by `yaw`, in a world of gravity `gravity_z`.
class PlanarMove : public ::testing::Test {
 protected:
  void spawn(const std::string& plugin, double yaw = 0, double gravity_z = 0) {
    sim_ = std::make_unique<Simulation>(flatWorldWithGravity(gravity_z), SimConfig());
    start_.position = Eigen::Vector3d(1, 2, 1);
    start_.orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    sim_->spawnRobot("box", parseRobot(boxUrdf(1.0, plugin), "box"), start_);
  }
  /// The box's displacement since the spawn, in the spawn's yaw frame.
  Eigen::Vector3d movedInStartFrame() const {
    return start_.orientation.inverse() * (sim_->modelPose("box").position - start_.position);
  }
  std::unique_ptr<Simulation> sim_;
  Pose3 start_;
};

std::string loadError(const std::string& plugin) {
  try {
    parseRobot(boxUrdf(1, planarMove(plugin)), "box");
  } catch (const LoadError& e) {
    return e.what();
  }
  return "loaded";
}

}  // namespace

TEST(PlanarMoveReader, TakesTheParametersAndThePluginsDefaults) {
  const RobotSpec bare = parseRobot(boxUrdf(1, planarMove("")), "box");
  ASSERT_TRUE(bare.planar_move);
  EXPECT_EQ(bare.planar_move->command_topic, "cmd_vel");
  EXPECT_EQ(bare.planar_move->odometry_topic, "odom");
  EXPECT_EQ(bare.planar_move->odometry_frame, "odom");
  EXPECT_EQ(bare.planar_move->robot_base_frame, "base_footprint");
  EXPECT_DOUBLE_EQ(bare.planar_move->odometry_rate_hz, 20);
  EXPECT_LT(bare.planar_move->cmd_timeout_s, 0);
  const RobotSpec given = parseRobot(
      boxUrdf(1, planarMove("<commandTopic>move</commandTopic><odometryTopic>o</odometryTopic>"
                            "<odometryFrame>world</odometryFrame><robotBaseFrame>body"
                            "</robotBaseFrame><odometryRate>50</odometryRate>"
                            "<cmdTimeout>0.25</cmdTimeout>")),
      "box");
  ASSERT_TRUE(given.planar_move);
  EXPECT_EQ(given.planar_move->command_topic, "move");
  EXPECT_EQ(given.planar_move->odometry_topic, "o");
  EXPECT_EQ(given.planar_move->odometry_frame, "world");
  EXPECT_EQ(given.planar_move->robot_base_frame, "body");
  EXPECT_DOUBLE_EQ(given.planar_move->odometry_rate_hz, 50);
  EXPECT_DOUBLE_EQ(given.planar_move->cmd_timeout_s, 0.25);
}

TEST(PlanarMoveReader, RefusesBadValuesNamingThePluginTheElementAndTheValue) {
  const std::string plugin = "box: <plugin name=\"move\" filename=\"libgazebo_ros_planar_move.so\">";
  EXPECT_EQ(loadError("<odometryRate>fast</odometryRate>"),
            plugin + " <odometryRate>: 'fast' is not a number");
  EXPECT_EQ(loadError("<odometryRate>-5</odometryRate>"),
            plugin + " <odometryRate>: '-5' is not a rate >= 0 Hz");
  EXPECT_EQ(loadError("<cmdTimeout>nan</cmdTimeout>"), plugin + " <cmdTimeout>: 'nan' is not a number");
  EXPECT_EQ(loadError("</plugin><plugin name='again' filename='libgazebo_ros_planar_move.so'>"),
            "box: <plugin name=\"again\" filename=\"libgazebo_ros_planar_move.so\">: a second "
            "libgazebo_ros_planar_move.so plugin");
}

TEST_F(PlanarMove, MovesByTheCommandInItsYawFrame) {
  spawn(planarMove(""), 0.5);
  sim_->setPlanarMoveCommand("box", 0.2, 0.1, 0);
  runFor(sim_.get(), 2.0);
  // 0.2 and 0.1 m/s for 2 s: (0.4, 0.2) in the box's frame, turned 0.5 rad in the world.
  // Nothing else acts: every step moves it by exactly v * dt, so only rounding is left.
  const Eigen::Vector3d moved = movedInStartFrame();
  EXPECT_NEAR(moved.x(), 0.4, 1e-9);
  EXPECT_NEAR(moved.y(), 0.2, 1e-9);
  EXPECT_NEAR(moved.z(), 0.0, 1e-9);
  EXPECT_NEAR(yawOf(sim_->modelPose("box").orientation), 0.5, 1e-9);
  const Twist3 v = sim_->modelTwist("box");
  EXPECT_NEAR(v.linear.x(), 0.2 * std::cos(0.5) - 0.1 * std::sin(0.5), 1e-9);
  EXPECT_NEAR(v.linear.y(), 0.1 * std::cos(0.5) + 0.2 * std::sin(0.5), 1e-9);
}

TEST_F(PlanarMove, AYawRateMovesItOnACircleOfRadiusSpeedOverRate) {
  spawn(planarMove(""));
  const double v = 0.5, w = 0.5, radius = v / w;  // 1 m, centred 1 m to the box's left
  sim_->setPlanarMoveCommand("box", v, 0, w);
  // Each step goes v dt along the yaw at its start: the path is a polygon inscribed in
  // the circle, whose corners lie within v dt of the circle's points at the same turn,
  // start + R (sin(w t), 1 - cos(w t)).
  const Eigen::Vector2d centre = start_.position.head<2>() + Eigen::Vector2d(0, radius);
  for (int quarter = 1; quarter <= 4; ++quarter) {
    runFor(sim_.get(), M_PI / 2 / w);  // a quarter turn, to the nearest step
    const double turned = w * sim_->timeS();
    const Pose3 pose = sim_->modelPose("box");
    const Eigen::Vector2d on_circle =
        start_.position.head<2>() +
        radius * Eigen::Vector2d(std::sin(turned), 1 - std::cos(turned));
    EXPECT_NEAR((pose.position.head<2>() - centre).norm(), radius, v * kStepS) << quarter;
    EXPECT_LT((pose.position.head<2>() - on_circle).norm(), v * kStepS) << quarter;
    EXPECT_NEAR(std::remainder(yawOf(pose.orientation) - turned, 2 * M_PI), 0, 1e-6) << quarter;
  }
}

TEST_F(PlanarMove, SetsTheVerticalSpeedToZeroAtEveryStep) {
  // In gravity the box falls during each step only: v = -g dt after it, so it sinks g dt^2
  // a step, 2000 * 9.8 * 1e-6 = 0.0196 m in 2 s (free fall would be 19.6 m).
  spawn(planarMove(""), 0, -9.8);
  runFor(sim_.get(), 2.0);
  EXPECT_NEAR(sim_->modelPose("box").position.z(), 1.0 - 2000 * 9.8 * kStepS * kStepS, 1e-9);
  EXPECT_NEAR(sim_->modelTwist("box").linear.z(), -9.8 * kStepS, 1e-9);
}

TEST_F(PlanarMove, ACommandOlderThanTheTimeoutStops) {
  spawn(planarMove("<cmdTimeout>0.5</cmdTimeout>"));
  sim_->setPlanarMoveCommand("box", 0.2, 0, 0);
  runFor(sim_.get(), 2.0);
  // Given until the step that starts more than 0.5 s after the command: 0.5 s, within two
  // steps, at 0.2 m/s; then at rest.
  EXPECT_NEAR(movedInStartFrame().x(), 0.2 * 0.5, 0.2 * 2 * kStepS);
  EXPECT_NEAR(sim_->modelTwist("box").linear.norm(), 0, 1e-12);
}

TEST_F(PlanarMove, OdometryIsTheModelPoseWithTheTwistBetweenReadings) {
  spawn(planarMove("<odometryFrame>map</odometryFrame><robotBaseFrame>body</robotBaseFrame>"),
        0.5);
  sim_->setPlanarMoveCommand("box", 0.2, 0.1, 0);
  runFor(sim_.get(), 0.5);
  sim_->readPlanarMoveOdometry("box");
  runFor(sim_.get(), 0.05);
  const OdometryData odom = sim_->readPlanarMoveOdometry("box");
  const Pose3 pose = sim_->modelPose("box");
  EXPECT_EQ(odom.frame_id, "map");
  EXPECT_EQ(odom.child_frame_id, "body");
  EXPECT_NEAR(odom.time_s, 0.55, 1e-9);
  EXPECT_LT((odom.pose.position - pose.position).norm(), 1e-12);
  EXPECT_LT(odom.pose.orientation.angularDistance(pose.orientation), 1e-12);
  // Moved (0.2, 0.1) * 0.05 s in the box's frame since the last reading.
  EXPECT_NEAR(odom.twist_in_child.linear.x(), 0.2, 1e-9);
  EXPECT_NEAR(odom.twist_in_child.linear.y(), 0.1, 1e-9);
  EXPECT_NEAR(odom.twist_in_child.angular.z(), 0.0, 1e-9);
  const double diagonal[6] = {1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3};
  for (int i = 0; i < 36; ++i) {
    EXPECT_EQ(odom.pose_covariance[i], i % 7 == 0 ? diagonal[i / 7] : 0.0) << i;
    EXPECT_EQ(odom.twist_covariance[i], 0.0) << i;
  }
}

TEST_F(PlanarMove, OdometryTurnRateIsTheYawTurnedBetweenReadings) {
  spawn(planarMove(""));
  sim_->setPlanarMoveCommand("box", 0, 0, 0.8);
  runFor(sim_.get(), 0.1);
  const OdometryData odom = sim_->readPlanarMoveOdometry("box");
  EXPECT_NEAR(odom.twist_in_child.angular.z(), 0.8, 1e-6);  // 0.08 rad in 0.1 s
}

TEST_F(PlanarMove, OdometryIsDueAtTheOdometryRateAndNeverAtRateZero) {
  for (const double rate : {20.0, 0.0}) {
    spawn(planarMove("<odometryRate>" + std::to_string(rate) + "</odometryRate>"));
    int due = 0;
    for (int k = 0; k < 1000; ++k) {
      for (const DueSensor& d : sim_->step()) due += d.kind == SensorKind::PlanarMoveOdometry;
    }
    EXPECT_EQ(due, static_cast<int>(rate)) << rate;
  }
}

TEST_F(PlanarMove, AResetTakesTheCommandAway) {
  spawn(planarMove(""));
  sim_->setPlanarMoveCommand("box", 0.3, 0, 0);
  runFor(sim_.get(), 0.2);
  sim_->reset();
  runFor(sim_.get(), 0.5);
  EXPECT_NEAR(movedInStartFrame().norm(), 0, 1e-12);
  EXPECT_NEAR(sim_->readPlanarMoveOdometry("box").twist_in_child.linear.norm(), 0, 1e-12);
}

TEST_F(PlanarMove, OnTheGroundFrictionTakesMuGDtOffTheSpeedAtEveryStep) {
  // The box resting on the ground (mu 1 both): within each step the contact's friction
  // slows it by at most mu g dt = 0.0098 m/s before the next step sets the command again,
  // so it slides at 0.2 - 0.0098 m/s: 0.3804 m in 2 s. It stays on the ground.
  sim_ = std::make_unique<Simulation>(flatWorld(), SimConfig());
  start_.position = Eigen::Vector3d(0, 0, 0.1);
  sim_->spawnRobot("box", parseRobot(boxUrdf(1.0, planarMove("")), "box"), start_);
  runFor(sim_.get(), 0.5);
  const Eigen::Vector3d before = sim_->modelPose("box").position;
  sim_->setPlanarMoveCommand("box", 0.2, 0, 0);
  runFor(sim_.get(), 2.0);
  const Eigen::Vector3d moved = sim_->modelPose("box").position - before;
  EXPECT_NEAR(moved.x(), (0.2 - 1.0 * 9.8 * kStepS) * 2.0, 1e-4);
  EXPECT_NEAR(moved.y(), 0, 1e-4);
  EXPECT_NEAR(moved.z(), 0, 1e-4);
}
