// Physics and diff-drive tests on the Burger, stepping the core by hand. Expected values
// come from the commands, the diff drive's ramp and what the tyres' friction lets the body do
// (burger_drive_model.h), worked out in the comments; the tolerances say which physical
// effect they allow for. test_traction.cpp drives the Burger at its tyres' limits.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "burger.h"
#include "burger_drive_model.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

constexpr double kDt = 0.001;

void run(Simulation* sim, double seconds) {
  const long steps = std::lround(seconds / kDt);
  for (long i = 0; i < steps; ++i) sim->step();
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

TEST(WorldOdometry, IsTheWorldPoseWhereverTheRobotWasSpawned) {
  // The same drive from the origin and from a spawn moved and turned: with the world as
  // its source the odometry is the world pose, so the second run's odometry is the first
  // one's carried by the spawn pose (encoder odometry would start from zero in both).
  Pose3 spawn;
  spawn.position = Eigen::Vector3d(1.0, -2.0, 0);
  spawn.orientation = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ());
  OdometryData odom[2];
  for (int i = 0; i < 2; ++i) {
    Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
    sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), i == 0 ? Pose3() : spawn);
    sim.setCmdVel("burger", 0.15, 0.5);
    run(&sim, 3.0);
    odom[i] = sim.readOdometry("burger");
  }
  const Eigen::Vector3d carried = spawn.position + spawn.orientation * odom[0].pose.position;
  // Not to the last bit: contacts are solved in another order and along other friction
  // axes when turned; 1 mm and 1 mrad after 0.45 m.
  EXPECT_LT((odom[1].pose.position - carried).norm(), 0.001);
  EXPECT_LT(odom[1].pose.orientation.angularDistance(spawn.orientation * odom[0].pose.orientation),
            0.001);
  // Round an arc of radius v / w = 0.3 m by w t = 1.5 rad less the ramp's
  // (0.19 - 0.11 m/s rims: 0.0125 m) / 0.16 = 0.078 rad: the chord 2 r sin(turn / 2) =
  // 0.389 m, less the creep below (3 % of the 0.45 m driven).
  const double turn_rad = 0.5 * 3.0 - (rampLossM(0.19) - rampLossM(0.11)) / kSeparationM;
  EXPECT_NEAR((odom[1].pose.position - spawn.position).norm(), 2 * 0.3 * std::sin(turn_rad / 2),
              0.03 * 0.45);
  EXPECT_EQ(odom[1].frame_id, "odom");
  EXPECT_EQ(odom[1].child_frame_id, "base_footprint");
  // The turn rate is the command's; forward the base runs about 3 % slower than its rims in
  // this arc (straight ahead 0.1 %). That is not the tyres' grip: it stays the same with
  // their mu at 0.2, 0.5 or 1.
  EXPECT_NEAR(odom[1].twist_in_child.angular.z(), 0.5, 0.005);
  EXPECT_NEAR(odom[1].twist_in_child.linear.x(), 0.15, 0.15 * 0.04);
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

  const double w = 1.0, t = 2.0;
  sim_.setCmdVel("burger", 0, w);
  run(&sim_, t);
  const JointStateData after = sim_.readJointStates("burger");
  // Turning left on the spot, each rim runs at w * 0.08 = 0.08 m/s for 2 s, less the ramp
  // (world time 0.5 s is a drive update: it starts at once), Tu * (0.047 + 0.013) = 0.0020 m:
  // 0.158 m, 4.79 rad of the 0.033 m wheels. The motors turn the wheels so, whatever the tyres
  // slip (their 10 N m against the 0.016 N m the slipping tyre's friction asks).
  const double rim_mps = w * kHalfTrackM, radius_m = 0.033;
  const double wheel_rad = (rim_mps * t - rampLossM(rim_mps)) / radius_m;
  for (const auto& [joint, sign] : {std::make_pair("wheel_left_joint", -1.0),
                                    std::make_pair("wheel_right_joint", 1.0)}) {
    const double turned = sign * (jointPosition(after, joint) - jointPosition(before, joint));
    EXPECT_NEAR(turned, wheel_rad, 0.002) << joint;
  }
  // The free flag keeps its heading while the robot turns under it, by the rims' travel over
  // half the track less what the tyres slip (burger_drive_model.h): its joint turns back by
  // about that (Bullet's hinge passes a few per cent of the pole's turn on to it).
  const double robot_turn_rad =
      2 * wheel_rad * radius_m / kSeparationM - spinSlipLossRad(rim_mps);  // 1.97
  EXPECT_NEAR(jointPosition(after, "flag_pole_joint") - jointPosition(before, "flag_pole_joint"),
              -robot_turn_rad, 0.1);
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
  // The base's collision box (0.140 long, centre 0.032 behind base_footprint) has its front
  // face 0.038 m ahead of base_footprint: pressed against the wall, base_footprint stops
  // that far from it, give or take the contact's depth and the shapes' 0.5 mm margins.
  EXPECT_NEAR(p.position.x(), wall_face_x + 0.038, 0.002);
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
  EXPECT_NEAR(jointPosition(js, "shoulder"), -0.5, 0.002);
}

TEST(CommandTimeout, ARobotWhoseCommandsStopIsStoppedAndFreshCommandsKeepItGoing) {
  SimConfig cfg;
  cfg.cmd_vel_timeout_s = 0.5;
  Simulation sim(bullet_sim_test::flatWorld(), cfg);
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  run(&sim, 1.0);  // settle
  const double start_x = sim.modelPose("burger").position.x();
  // One command of 0.2 m/s, dropped after 0.5 s (world times 1 s and 1.5 s are drive
  // updates). Without slip the ramp down would give back what the ramp up lost: 0.1 m. But
  // the tyres let the body speed up at 0.825 m/s^2 and slow down at 0.98 m/s^2 only
  // (burger_drive_model.h), so it falls v^2 / (2 a) = 0.0242 m behind getting going and
  // runs v^2 / (2 mu g) = 0.0204 m on stopping: 0.0962 m. Bullet's contacts brake up to 5 %
  // weaker (1.0 mm more) and the timeout's check may come a physics step late (0.2 mm).
  const double v = 0.2;
  const double hand_m =
      v * 0.5 - v * v / (2 * forwardLimitMps2()) + v * v / (2 * brakingLimitMps2());
  sim.setCmdVel("burger", v, 0);
  run(&sim, 2.5);
  const double stopped_x = sim.modelPose("burger").position.x();
  EXPECT_GE(stopped_x - start_x, hand_m - 0.0005);
  EXPECT_LE(stopped_x - start_x, hand_m + 0.0015);
  run(&sim, 0.5);
  EXPECT_LT(std::fabs(sim.modelPose("burger").position.x() - stopped_x), 0.001);
  // Commands every 0.25 s (inside the timeout) keep it going: 2 s at 0.2 m/s from world time
  // 4 s (a drive update) less the 0.0242 m the body falls behind getting going, and the
  // tyres' creep, 0.1 % of the way (0.4 mm).
  for (int i = 0; i < 8; ++i) {
    sim.setCmdVel("burger", v, 0);
    run(&sim, 0.25);
  }
  const double kept_m = sim.modelPose("burger").position.x() - stopped_x;
  const double kept_hand_m = v * 2.0 - v * v / (2 * forwardLimitMps2());
  EXPECT_LE(kept_m, kept_hand_m + 0.0005);
  EXPECT_GE(kept_m, kept_hand_m - 0.001);
}

// The Burger's wheels have radius 0.033 m and are 0.160 m apart.
constexpr double kWheelRadiusM = 0.033;

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
