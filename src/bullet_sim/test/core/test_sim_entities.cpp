// Simulation's link, joint, external-force, physics-setting and spawn-generation methods,
// on bodies in free space (no ground, set gravity) whose motion is worked out by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/simulation.h"

using namespace bullet_sim;

namespace {

constexpr double kDt = 0.001;

/// A 2 kg box with izz 0.1 kg m^2.
const char* kBoxUrdf = R"(<robot name="box">
  <link name="body">
    <inertial><mass value="2"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
</robot>)";

/// A base (izz 0.2) and a wheel (izz 0.02) on a continuous joint about z, 0.3 m above;
/// both centres of mass on the axis.
const char* kRotorUrdf = R"(<robot name="rotor">
  <link name="base">
    <inertial><mass value="4"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <joint name="spin" type="continuous"><parent link="base"/><child link="wheel"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/></joint>
  <link name="wheel">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.02"/></inertial>
    <collision><origin xyz="0.1 0 0"/><geometry><box size="0.1 0.05 0.02"/></geometry></collision>
  </link>
</robot>)";

WorldSpec freeSpace(const Eigen::Vector3d& gravity) {
  WorldSpec world;
  world.name = "free_space";
  world.gravity = gravity;
  return world;
}

Pose3 at(double x, double y, double z, double yaw = 0) {
  Pose3 p;
  p.position = {x, y, z};
  p.orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  return p;
}

void run(Simulation* sim, int steps) {
  for (int i = 0; i < steps; ++i) sim->step();
}

class FreeSpace : public ::testing::Test {
 protected:
  FreeSpace() : sim(freeSpace({0, 0, 0}), config()) {
    sim.spawnRobot("box", parseRobot(kBoxUrdf, "box.urdf"), at(0, 0, 5));
    sim.spawnRobot("rotor", parseRobot(kRotorUrdf, "rotor.urdf"), at(3, 0, 5, 0.4));
  }
  static SimConfig config() {
    SimConfig c;
    c.physics_step_s = kDt;
    return c;
  }
  Simulation sim;
};

}  // namespace

TEST_F(FreeSpace, AWrenchForTSecondsChangesVelocityByImpulseOverMass) {
  // 4 N for 0.25 s on 2 kg: 0.5 m/s. 0.3 N m for 0.25 s on izz 0.1: 0.75 rad/s.
  sim.externalForces().addWrench({"box", "body", {{4, 0, 0}, {0, 0, 0.3}}, {0, 0.25}}, sim.timeS());
  run(&sim, 400);
  const Twist3 v = sim.modelTwist("box");
  EXPECT_NEAR(v.linear.x(), 0.5, 1e-9);
  EXPECT_NEAR(v.angular.z(), 0.75, 1e-9);
  EXPECT_EQ(sim.externalForces().wrenchCount(), 0u);
}

TEST_F(FreeSpace, AnUnendingWrenchActsUntilCleared) {
  sim.externalForces().addWrench({"box", "body", {{0, 2, 0}, {}}, {0, -1}}, sim.timeS());
  run(&sim, 100);
  EXPECT_EQ(sim.externalForces().clearWrenches("box", "body"), 1u);
  run(&sim, 100);
  EXPECT_NEAR(sim.modelTwist("box").linear.y(), 2.0 / 2.0 * 0.1, 1e-9);
}

TEST_F(FreeSpace, AJointEffortSpinsWheelAndBaseApart) {
  // Equal and opposite torques: relative rate tau T (1 / I_wheel + 1 / I_base).
  sim.externalForces().addEffort({"rotor", "spin", 0.01, {0, 0.5}}, sim.timeS());
  run(&sim, 600);
  EXPECT_NEAR(sim.jointVelocity("rotor", "spin"), 0.01 * 0.5 * (1 / 0.02 + 1 / 0.2), 1e-4);
  EXPECT_NEAR(sim.linkState("rotor", "base").twist.angular.z(), -0.01 * 0.5 / 0.2, 1e-4);
}

TEST_F(FreeSpace, JointPositionsTurnTheChildAboutTheAxis) {
  sim.setJointPositions("rotor", {{"spin", 1.0}});
  EXPECT_NEAR(sim.jointPosition("rotor", "spin"), 1.0, 1e-9);
  const EntityState wheel = sim.linkState("rotor", "wheel");
  // Base at (3, 0, 5) turned 0.4; the wheel 0.3 m above, turned 0.4 + 1.0.
  EXPECT_NEAR((wheel.pose.position - Eigen::Vector3d(3, 0, 5.3)).norm(), 0, 1e-9);
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(1.4, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(wheel.pose.orientation.angularDistance(expected), 0, 1e-9);
  run(&sim, 100);  // at rest, nothing drives it: it stays there
  EXPECT_NEAR(sim.jointPosition("rotor", "spin"), 1.0, 1e-6);
  EXPECT_THROW(sim.setJointPositions("rotor", {{"nope", 1.0}}), std::out_of_range);
}

TEST_F(FreeSpace, SettingALinkStateMovesTheWholeModel) {
  sim.setJointPositions("rotor", {{"spin", 0.5}});
  sim.setLinkState("rotor", "wheel", at(-1, 2, 3, 0), Twist3{});
  const EntityState wheel = sim.linkState("rotor", "wheel");
  EXPECT_NEAR((wheel.pose.position - Eigen::Vector3d(-1, 2, 3)).norm(), 0, 1e-9);
  // The base keeps its place under the wheel: 0.3 m below, turned back by the joint angle.
  const EntityState base = sim.linkState("rotor", "base");
  EXPECT_NEAR((base.pose.position - Eigen::Vector3d(-1, 2, 2.7)).norm(), 0, 1e-9);
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(base.pose.orientation.angularDistance(expected), 0, 1e-9);
  EXPECT_NEAR(sim.jointPosition("rotor", "spin"), 0.5, 1e-9);
}

TEST_F(FreeSpace, EntitiesAndJointsAreFoundByGazeboNames) {
  ASSERT_TRUE(sim.findEntity("rotor::wheel"));
  EXPECT_EQ(sim.findEntity("rotor::wheel")->link, "wheel");
  EXPECT_EQ(sim.findEntity("box")->link, "");
  EXPECT_FALSE(sim.findEntity("rotor::axle"));
  EXPECT_FALSE(sim.findEntity("wheel"));
  EXPECT_FALSE(sim.findEntity("world"));
  EXPECT_NEAR(sim.frameState("world")->pose.position.norm(), 0, 0);
  EXPECT_NEAR((sim.frameState("rotor")->pose.position - Eigen::Vector3d(3, 0, 5)).norm(), 0, 1e-9);
  EXPECT_FALSE(sim.frameState("ghost"));
  EXPECT_NEAR(sim.frameState("map")->pose.position.norm(), 0, 0);
  EXPECT_EQ(sim.findJoint("spin")->model, "rotor");
  EXPECT_EQ(sim.findJoint("rotor::spin")->link, "spin");
  EXPECT_FALSE(sim.findJoint("box::spin"));
  EXPECT_EQ(sim.linkNames("rotor"), (std::vector<std::string>{"base", "wheel"}));
  EXPECT_EQ(sim.jointNames("rotor"), std::vector<std::string>{"spin"});
  EXPECT_EQ(sim.rootLink("rotor"), "base");
}

TEST_F(FreeSpace, ANewPhysicsStepKeepsTimeRunningOn) {
  run(&sim, 100);
  sim.setPhysicsStep(0.002);
  EXPECT_NEAR(sim.timeS(), 0.1, 1e-12);
  run(&sim, 50);
  EXPECT_NEAR(sim.timeS(), 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(sim.physicsStepS(), 0.002);
  EXPECT_THROW(sim.setPhysicsStep(0.0), std::invalid_argument);
}

TEST_F(FreeSpace, NewGravityActsFromTheNextStep) {
  sim.setGravity({0, 0, -2});
  run(&sim, 500);
  EXPECT_NEAR(sim.modelTwist("box").linear.z(), -2 * 0.5, 1e-9);
  EXPECT_EQ(sim.gravity(), Eigen::Vector3d(0, 0, -2));
  sim.reset();  // a reset rebuilds the world with the gravity set
  run(&sim, 500);
  EXPECT_NEAR(sim.modelTwist("box").linear.z(), -2 * 0.5, 1e-9);
}

TEST(SpawnGeneration, EverySpawnGetsANumberNeverUsedBefore) {
  WorldSpec world = freeSpace({0, 0, 0});
  world.models.push_back({"crate", parseRobot(kBoxUrdf, "crate.urdf"), at(0, 0, 1)});
  Simulation sim(world, SimConfig());
  const RobotSpec box = parseRobot(kBoxUrdf, "box.urdf");
  sim.spawnRobot("box", box, at(1, 0, 1));
  // The world's movable models first, then the spawns, in order.
  EXPECT_EQ(sim.spawnGeneration("crate"), 0);
  EXPECT_EQ(sim.spawnGeneration("box"), 1);
  ASSERT_TRUE(sim.deleteRobot("box"));
  sim.spawnRobot("box", box, at(1, 0, 1));
  EXPECT_EQ(sim.spawnGeneration("box"), 2);
  sim.reset();  // rebuilds the same spawns: their numbers stay
  EXPECT_EQ(sim.spawnGeneration("crate"), 0);
  EXPECT_EQ(sim.spawnGeneration("box"), 2);
  EXPECT_THROW(sim.spawnGeneration("nobody"), std::out_of_range);
}
