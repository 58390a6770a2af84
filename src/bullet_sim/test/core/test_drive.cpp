// Physics and diff-drive tests on the Burger, stepping the core by hand.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "burger.h"

using namespace bullet_sim;

namespace {

constexpr double kDt = 0.001;

double yawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
}

void run(Simulation* sim, double seconds) {
  const long steps = std::lround(seconds / kDt);
  for (long i = 0; i < steps; ++i) sim->step();
}

/// Heading accumulated step by step, so that turns beyond pi are measured.
double turnFor(Simulation* sim, double seconds) {
  double heading = 0, last = yawOf(sim->modelPose("burger").orientation);
  const long steps = std::lround(seconds / kDt);
  for (long i = 0; i < steps; ++i) {
    sim->step();
    const double now = yawOf(sim->modelPose("burger").orientation);
    heading += std::remainder(now - last, 2 * M_PI);
    last = now;
  }
  return heading;
}

double jointPosition(const JointStateData& js, const std::string& name) {
  for (size_t i = 0; i < js.names.size(); ++i) {
    if (js.names[i] == name) return js.positions[i];
  }
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

double jointVelocity(const JointStateData& js, const std::string& name) {
  for (size_t i = 0; i < js.names.size(); ++i) {
    if (js.names[i] == name) return js.velocities[i];
  }
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

/// The Burger with <limit velocity="2.0"> on both (continuous) wheel joints.
RobotSpec burgerWithWheelLimit() {
  std::string urdf = bullet_sim_test::burgerUrdf();
  for (const std::string side : {"left", "right"}) {
    const std::string joint = "<joint name=\"wheel_" + side + "_joint\" type=\"continuous\">";
    const size_t at = urdf.find(joint);
    if (at == std::string::npos) throw std::runtime_error("no " + joint + " in the Burger");
    urdf.insert(at + joint.size(), "<limit effort=\"1\" velocity=\"2.0\"/>");
  }
  return parseRobot(urdf, "robot_description");
}

class BurgerOnFlatGround : public ::testing::Test {
 protected:
  BurgerOnFlatGround() : sim_(bullet_sim_test::flatWorld(), SimConfig()) {
    sim_.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  }
  Simulation sim_;
};

}  // namespace

TEST_F(BurgerOnFlatGround, StaysWhereItIsWithoutACommand) {
  run(&sim_, 1.0);  // settle onto wheels and caster
  const Pose3 settled = sim_.modelPose("burger");
  run(&sim_, 20.0);
  const Pose3 later = sim_.modelPose("burger");
  EXPECT_LT((later.position - settled.position).norm(), 0.001);
  EXPECT_LT(std::fabs(std::remainder(yawOf(later.orientation) - yawOf(settled.orientation), 2 * M_PI)),
            0.001);
}

TEST_F(BurgerOnFlatGround, DrivesStraightOneMetreInFiveSeconds) {
  sim_.setCmdVel("burger", 0.2, 0);
  run(&sim_, 5.0);
  const Pose3 p = sim_.modelPose("burger");
  EXPECT_NEAR(p.position.x(), 1.0, 0.03);
  EXPECT_LT(std::fabs(p.position.y()), 0.02);
  EXPECT_NEAR(p.position.z(), 0.0, 0.005);
}

TEST_F(BurgerOnFlatGround, TurnsPiRadiansInPiSeconds) {
  sim_.setCmdVel("burger", 0, 1.0);
  const double heading = turnFor(&sim_, M_PI);
  EXPECT_NEAR(heading, M_PI, 0.03 * M_PI);
  EXPECT_LT(sim_.modelPose("burger").position.head<2>().norm(), 0.02);
}

TEST_F(BurgerOnFlatGround, WorldOdometryIsTheTrueWorldPose) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  Pose3 spawn;
  spawn.position = Eigen::Vector3d(1.0, -2.0, 0);
  spawn.orientation = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), spawn);
  sim.setCmdVel("burger", 0.15, 0.5);
  run(&sim, 3.0);
  const OdometryData odom = sim.readOdometry("burger");
  const Pose3 truth = sim.modelPose("burger");
  EXPECT_NEAR((odom.pose.position - truth.position).norm(), 0, 1e-9);
  EXPECT_NEAR(odom.pose.orientation.angularDistance(truth.orientation), 0, 1e-9);
  // Driving a 0.3 m radius arc for 3 s (ramps aside) moves it well away from the spawn point.
  EXPECT_GT((truth.position - spawn.position).norm(), 0.3);
  EXPECT_EQ(odom.frame_id, "odom");
  EXPECT_EQ(odom.child_frame_id, "base_footprint");
  EXPECT_NEAR(odom.twist_in_child.linear.x(), 0.15, 0.01);
  EXPECT_NEAR(odom.twist_in_child.angular.z(), 0.5, 0.02);
}

TEST(EncoderOdometry, AgreesWithTheTruePose) {
  RobotSpec spec = bullet_sim_test::burgerSpec();
  spec.diff_drive->odometry_source = OdomSource::Encoder;
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", spec, Pose3());
  sim.setCmdVel("burger", 0.2, 0.4);
  run(&sim, 4.0);
  const OdometryData odom = sim.readOdometry("burger");
  const Pose3 truth = sim.modelPose("burger");
  EXPECT_NEAR(odom.pose.position.x(), truth.position.x(), 0.03);
  EXPECT_NEAR(odom.pose.position.y(), truth.position.y(), 0.03);
  EXPECT_NEAR(yawOf(odom.pose.orientation), yawOf(truth.orientation), 0.05);
}

TEST_F(BurgerOnFlatGround, JointStatesCarryWheelsAndFlagAndTheFlagLagsInATurn) {
  run(&sim_, 0.5);
  const JointStateData before = sim_.readJointStates("burger");
  ASSERT_EQ(before.names.size(), 3u);
  EXPECT_EQ(before.names[0], "flag_pole_joint");
  EXPECT_EQ(before.names[1], "wheel_left_joint");
  EXPECT_EQ(before.names[2], "wheel_right_joint");
  EXPECT_EQ(before.positions.size(), 3u);
  EXPECT_EQ(before.velocities.size(), 3u);
  EXPECT_EQ(before.efforts.size(), 3u);

  sim_.setCmdVel("burger", 0, 1.0);
  run(&sim_, 2.0);
  const JointStateData after = sim_.readJointStates("burger");
  // A free flag keeps its heading while the robot turns under it.
  EXPECT_GT(std::fabs(jointPosition(after, "flag_pole_joint") -
                      jointPosition(before, "flag_pole_joint")),
            0.5);
  // Turning left: the left wheel runs backwards, the right one forwards.
  EXPECT_LT(jointPosition(after, "wheel_left_joint"), jointPosition(before, "wheel_left_joint") - 1);
  EXPECT_GT(jointPosition(after, "wheel_right_joint"), jointPosition(before, "wheel_right_joint") + 1);
}

TEST(WallContact, FullSpeedIntoAWallForTenSecondsStopsInFrontOfIt) {
  Simulation sim(loadWorldFile(bullet_sim_test::roundTrackPath()), SimConfig());
  Pose3 spawn;  // in the west lane, facing the lane's west wall (centre x -0.80941)
  spawn.orientation = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), spawn);
  sim.setCmdVel("burger", 0.22, 0);
  const double wall_face_x = -0.80941 + 0.015 / 2;
  double min_x = 0;
  for (int i = 0; i < 10000; ++i) {
    sim.step();
    for (const LinkPose& link : sim.linkPoses("burger")) {
      min_x = std::min(min_x, link.pose.position.x());
    }
  }
  EXPECT_GT(min_x, wall_face_x);  // no link origin ever beyond the wall
  const Pose3 p = sim.modelPose("burger");
  // The base's front face is 0.038 m ahead of base_footprint: it got there.
  EXPECT_LT(p.position.x(), wall_face_x + 0.038 + 0.03);
  EXPECT_GT(p.position.x(), wall_face_x + 0.038 - 0.01);
  EXPECT_NEAR(p.position.z(), 0, 0.02);  // still on its wheels
}

TEST(Determinism, SameSeedSameCommandsGiveIdenticalResults) {
  auto runOnce = [](uint64_t seed) {
    SimConfig cfg;
    cfg.seed = seed;
    Simulation sim(loadWorldFile(bullet_sim_test::roundTrackPath()), cfg);
    Pose3 spawn;
    spawn.orientation = Eigen::AngleAxisd(1.5675, Eigen::Vector3d::UnitZ());
    sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), spawn);
    sim.setCmdVel("burger", 0.2, 0.3);
    run(&sim, 2.0);
    return std::make_pair(sim.modelPose("burger"), sim.readRay("burger", 0).ranges);
  };
  const auto a = runOnce(7), b = runOnce(7), c = runOnce(8);
  EXPECT_EQ(a.first.position, b.first.position);
  EXPECT_EQ(a.first.orientation.coeffs(), b.first.orientation.coeffs());
  EXPECT_EQ(a.second, b.second);
  EXPECT_NE(a.second, c.second);  // the seed reaches the lidar noise
}

TEST_F(BurgerOnFlatGround, ResetReplaysIdentically) {
  sim_.setCmdVel("burger", 0.2, 0.5);
  run(&sim_, 1.0);
  const Pose3 first = sim_.modelPose("burger");
  sim_.reset();
  EXPECT_EQ(sim_.timeS(), 0.0);
  EXPECT_LT(sim_.modelPose("burger").position.norm(), 1e-9);
  sim_.setCmdVel("burger", 0.2, 0.5);
  run(&sim_, 1.0);
  EXPECT_NEAR((sim_.modelPose("burger").position - first.position).norm(), 0, 1e-9);
}

TEST(Joints, RevoluteLimitHoldsAFallingArmAndPrismaticIsHeldFixedWithAWarning) {
  const char* urdf = R"(<robot name="arm">
    <link name="base">
      <collision><origin xyz="0 0 0.05"/><geometry><box size="0.4 0.4 0.1"/></geometry></collision>
      <inertial><origin xyz="0 0 0.05"/><mass value="5"/>
        <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    </link>
    <link name="arm">
      <inertial><origin xyz="0 0.2 0"/><mass value="0.1"/>
        <inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    </link>
    <joint name="shoulder" type="revolute">
      <parent link="base"/><child link="arm"/><origin xyz="0 0 0.3"/><axis xyz="1 0 0"/>
      <limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>
    </joint>
    <link name="slider">
      <inertial><mass value="0.01"/>
        <inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial>
    </link>
    <joint name="rail" type="prismatic">
      <parent link="base"/><child link="slider"/><axis xyz="1 0 0"/>
      <limit lower="0" upper="0.1" effort="1" velocity="1"/>
    </joint>
  </robot>)";
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("arm", parseRobot(urdf, "arm.urdf"), Pose3());
  bool warned = false;
  for (const std::string& w : sim.robotSpec("arm").warnings) {
    warned = warned || w.find("joint 'rail': type not supported") != std::string::npos;
  }
  EXPECT_TRUE(warned);
  run(&sim, 1.0);
  const JointStateData js = sim.readJointStates("arm");
  ASSERT_EQ(js.names.size(), 1u);  // the prismatic joint is held fixed
  // The arm's mass sits on +y: gravity turns it about +x down to the lower limit.
  EXPECT_NEAR(jointPosition(js, "shoulder"), -0.5, 0.03);
}

TEST(CommandTimeout, ARobotWhoseCommandsStopIsStoppedAndFreshCommandsKeepItGoing) {
  SimConfig cfg;
  cfg.cmd_vel_timeout_s = 0.5;
  Simulation sim(bullet_sim_test::flatWorld(), cfg);
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  run(&sim, 1.0);  // settle
  const double start_x = sim.modelPose("burger").position.x();
  // One command of 0.2 m/s: about 0.5 s of driving (0.2 s up and down the Burger's 1 m/s^2
  // ramps), 0.1 m in all, then it stands still.
  sim.setCmdVel("burger", 0.2, 0);
  run(&sim, 2.5);
  const double stopped_x = sim.modelPose("burger").position.x();
  EXPECT_NEAR(stopped_x - start_x, 0.1, 0.03);
  run(&sim, 0.5);
  EXPECT_LT(std::fabs(sim.modelPose("burger").position.x() - stopped_x), 0.001);
  // Commands every 0.25 s (inside the timeout) keep it going: 2 s at 0.2 m/s.
  for (int i = 0; i < 8; ++i) {
    sim.setCmdVel("burger", 0.2, 0);
    run(&sim, 0.25);
  }
  EXPECT_GT(sim.modelPose("burger").position.x() - stopped_x, 0.35);
}

// The Burger's wheels have radius 0.033 m and are 0.160 m apart.
constexpr double kWheelRadiusM = 0.033, kHalfTrackM = 0.080;

TEST(WheelLimits, CommandBeyondTheWheelLimitIsScaledToIt) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", burgerWithWheelLimit(), Pose3());
  sim.setCmdVel("burger", 10.0, 0);  // 303 rad/s unclamped
  run(&sim, 2.0);
  const JointStateData js = sim.readJointStates("burger");
  EXPECT_LE(std::fabs(jointVelocity(js, "wheel_left_joint")), 2.0 + 0.02);
  EXPECT_LE(std::fabs(jointVelocity(js, "wheel_right_joint")), 2.0 + 0.02);
  EXPECT_NEAR(jointVelocity(js, "wheel_left_joint"), 2.0, 0.05);
  // Rolling without slip: 2.0 rad/s * 0.033 m = 0.066 m/s.
  EXPECT_NEAR(sim.modelTwist("burger").linear.head<2>().norm(), 2.0 * kWheelRadiusM, 0.004);
  const std::vector<std::string> warnings = sim.takeWarnings();
  ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(warnings);
  EXPECT_NE(warnings[0].find("model 'burger': cmd_vel 10 m/s, 0 rad/s turns a wheel faster than "
                             "its joint's <limit velocity>: scaled by 0.0066"),
            std::string::npos)
      << warnings[0];
}

TEST(WheelLimits, ScaledTurnKeepsTheRatioOfTheWheelsAndIsToldOnce) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", burgerWithWheelLimit(), Pose3());
  sim.takeWarnings();
  // Rim speeds 10 -+ 50 * 0.08 = 6 and 14 m/s: the right wheel sets the scale, 2.0 rad/s,
  // and the left one follows at 2.0 * 6 / 14 rad/s.
  sim.setCmdVel("burger", 10.0, 50.0);
  run(&sim, 1.0);
  sim.setCmdVel("burger", 10.0, 50.0);
  run(&sim, 1.0);
  const JointStateData js = sim.readJointStates("burger");
  EXPECT_NEAR(jointVelocity(js, "wheel_right_joint"), 2.0, 0.05);
  EXPECT_NEAR(jointVelocity(js, "wheel_left_joint"), 2.0 * 6.0 / 14.0, 0.05);
  // Turn rate (right - left) r / track: (2.0 - 0.857) * 0.033 / 0.16 = 0.236 rad/s.
  EXPECT_NEAR(sim.modelTwist("burger").angular.z(),
              2.0 * (1.0 - 6.0 / 14.0) * kWheelRadiusM / (2 * kHalfTrackM), 0.01);
  EXPECT_EQ(sim.takeWarnings().size(), 1u);
}

TEST(WheelLimits, CommandWithinTheLimitIsUntouched) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", burgerWithWheelLimit(), Pose3());
  sim.takeWarnings();
  sim.setCmdVel("burger", 0.05, 0);  // 1.52 rad/s
  run(&sim, 2.0);
  EXPECT_NEAR(jointVelocity(sim.readJointStates("burger"), "wheel_left_joint"),
              0.05 / kWheelRadiusM, 0.05);
  EXPECT_TRUE(sim.takeWarnings().empty());
}
