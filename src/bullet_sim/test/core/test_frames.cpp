// Frame math, external-force bookkeeping and model properties: the ROS-free parts behind
// the /gazebo services, checked against values worked out by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "bullet_sim/description/model_properties.h"
#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/world/entity_frames.h"
#include "bullet_sim/world/external_forces.h"

using namespace bullet_sim;

namespace {

Pose3 yawPose(double x, double y, double z, double yaw) {
  Pose3 p;
  p.position = {x, y, z};
  p.orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  return p;
}

double yawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
}

void expectNear(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, 1e-12) << actual.transpose() << " vs "
                                                      << expected.transpose();
}

/// Counts the steps of length dt from t = 0 in which one entry acts.
int activeSteps(const ForceWindow& window, double dt, int max_steps) {
  ExternalForces forces;
  forces.addEffort({"robot", "joint", 1.0, window}, 0.0);
  int active = 0;
  for (int k = 0; k < max_steps; ++k) active += static_cast<int>(forces.effortsAt(k * dt).size());
  return active;
}

const char* kRotorUrdf = R"(<robot name="rotor">
  <link name="base">
    <inertial><origin xyz="0 0 0.01"/><mass value="4"/>
      <inertia ixx="0.1" ixy="0.001" ixz="0.002" iyy="0.15" iyz="0.003" izz="0.2"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
    <collision><origin xyz="0 0 -0.2"/><geometry><sphere radius="0.05"/></geometry></collision>
  </link>
  <joint name="spin" type="continuous"><parent link="base"/><child link="wheel"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/></joint>
  <link name="wheel">
    <collision name="wheel_shape"><geometry><cylinder radius="0.2" length="0.02"/></geometry></collision>
  </link>
  <joint name="mount" type="fixed"><parent link="base"/><child link="tag"/></joint>
  <link name="tag"/>
</robot>)";

}  // namespace

TEST(EntityFrames, RelativeStateIsThePoseAndTwistSeenFromTheFrame) {
  // Frame at (1, 2, 0) facing +y, moving at (0, 1, 0); entity 1 m ahead of it (at
  // (1, 3, 0)), turned a further 0.3 rad, moving at (1, 1, 0) and turning at 0.5 rad/s.
  EntityState frame{yawPose(1, 2, 0, M_PI / 2), {{0, 1, 0}, {0, 0, 0.2}}};
  EntityState entity{yawPose(1, 3, 0, M_PI / 2 + 0.3), {{1, 1, 0}, {0, 0, 0.5}}};
  const EntityState rel = expressIn(entity, frame);
  expectNear(rel.pose.position, {1, 0, 0});
  EXPECT_NEAR(yawOf(rel.pose.orientation), 0.3, 1e-12);
  // Velocity difference (1, 0, 0) in world axes is -y in the frame's axes.
  expectNear(rel.twist.linear, {0, -1, 0});
  expectNear(rel.twist.angular, {0, 0, 0.3});
}

TEST(EntityFrames, StateInWorldUndoesTheRelativePoseAndRotatesTheTwist) {
  const Pose3 frame = yawPose(-2, 1, 0.5, -0.7);
  EntityState rel{yawPose(0.4, -0.3, 0.1, 1.1), {{1, 0, 0}, {0, 0, 2}}};
  const EntityState world = stateInWorld(rel, frame);
  const EntityState back = expressIn(world, EntityState{frame, Twist3{}});
  expectNear(back.pose.position, rel.pose.position);
  EXPECT_NEAR(yawOf(back.pose.orientation), 1.1, 1e-12);
  // (1, 0, 0) in a frame turned by -0.7 about z points at (cos -0.7, sin -0.7, 0).
  expectNear(world.twist.linear, {std::cos(-0.7), std::sin(-0.7), 0});
  expectNear(world.twist.angular, {0, 0, 2});
}

TEST(EntityFrames, WrenchAtAReferencePointAddsItsMomentThenTurnsIntoWorldAxes) {
  // 2 N along the frame's x, acting 0.5 m along its y: moment p x F = (0, 0, -1) N m.
  const Wrench w = wrenchInWorld({2, 0, 0}, {0, 0, 0.25}, {0, 0.5, 0},
                                 Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  expectNear(w.force_n, {0, 2, 0});
  expectNear(w.torque_nm, {0, 0, -0.75});
}

TEST(EntityFrames, NamesSplitIntoModelAndLink) {
  const std::vector<std::string> models = {"tb3", "tb3_1"};
  ASSERT_TRUE(splitEntityName("tb3_1::base_link", models));
  EXPECT_EQ(splitEntityName("tb3_1::base_link", models)->model, "tb3_1");
  EXPECT_EQ(splitEntityName("tb3_1::base_link", models)->link, "base_link");
  EXPECT_EQ(splitEntityName("tb3", models)->link, "");
  EXPECT_FALSE(splitEntityName("tb3_2", models));
  EXPECT_FALSE(splitEntityName("tb3::", models));
  EXPECT_FALSE(splitEntityName("", models));
  EXPECT_TRUE(isWorldFrameName(""));
  EXPECT_TRUE(isWorldFrameName("world"));
  EXPECT_FALSE(isWorldFrameName("map"));
}

TEST(EntityFrames, NonFinitePosesAndTwistsAreNotUsable) {
  Pose3 pose;
  EXPECT_TRUE(isUsablePose(pose));
  pose.orientation.coeffs().setZero();  // a zero quaternion means no rotation
  EXPECT_TRUE(isUsablePose(pose));
  pose.position.y() = std::nan("");
  EXPECT_FALSE(isUsablePose(pose));
  Twist3 twist;
  EXPECT_TRUE(isFiniteTwist(twist));
  twist.angular.z() = INFINITY;
  EXPECT_FALSE(isFiniteTwist(twist));
}

TEST(ExternalForces, ADurationActsForThatManySteps) {
  EXPECT_EQ(activeSteps({0.0, 0.005}, 0.001, 100), 5);
  EXPECT_EQ(activeSteps({0.0, 0.25}, 0.001, 1000), 250);
  EXPECT_EQ(activeSteps({0.0, 0.0}, 0.001, 100), 1);      // zero: one step
  EXPECT_EQ(activeSteps({0.0, -1.0}, 0.001, 100), 100);   // negative: until cleared
  EXPECT_EQ(activeSteps({0.010, 0.003}, 0.001, 100), 3);  // later start
}

TEST(ExternalForces, AStartInThePastMeansNowAndClearingRemovesOneTarget) {
  ExternalForces forces;
  BodyWrench wrench{"a", "link", {}, {0.0, 0.002}};
  forces.addWrench(wrench, 1.0);  // start 0 asked at t = 1: acts from 1
  EXPECT_EQ(forces.wrenchesAt(1.0).size(), 1u);
  EXPECT_EQ(forces.wrenchesAt(1.001).size(), 1u);
  EXPECT_EQ(forces.wrenchesAt(1.002).size(), 0u);
  EXPECT_EQ(forces.wrenchCount(), 0u);  // expired entries are dropped

  forces.addWrench({"a", "link", {}, {0, -1}}, 0);
  forces.addWrench({"a", "other", {}, {0, -1}}, 0);
  forces.addEffort({"b", "joint", 2.0, {0, -1}}, 0);
  EXPECT_EQ(forces.clearWrenches("a", "link"), 1u);
  EXPECT_EQ(forces.clearWrenches("a", "link"), 0u);
  EXPECT_EQ(forces.wrenchCount(), 1u);
  forces.clearRobot("a");
  EXPECT_EQ(forces.wrenchCount(), 0u);
  EXPECT_EQ(forces.effortCount(), 1u);
  EXPECT_EQ(forces.clearEfforts("b", "joint"), 1u);
}

TEST(ModelProperties, InertiaCollisionsAndJointTypesComeFromTheUrdf) {
  const RobotSpec spec = parseRobot(kRotorUrdf, "rotor.urdf");
  const LinkInertia base = linkInertia(spec, "base");
  EXPECT_DOUBLE_EQ(base.mass_kg, 4.0);
  EXPECT_DOUBLE_EQ(base.com_in_link.position.z(), 0.01);
  EXPECT_DOUBLE_EQ(base.ixy, 0.001);
  EXPECT_DOUBLE_EQ(base.iyz, 0.003);
  EXPECT_DOUBLE_EQ(base.izz, 0.2);
  EXPECT_DOUBLE_EQ(linkInertia(spec, "tag").mass_kg, 0.0);
  EXPECT_THROW(linkInertia(spec, "nothing"), std::out_of_range);

  const std::vector<std::string> expected = {"base_collision", "base_collision_1", "wheel_shape"};
  EXPECT_EQ(collisionNames(spec), expected);

  EXPECT_EQ(jointKind(spec, "spin"), JointKind::Continuous);
  EXPECT_EQ(jointKind(spec, "mount"), JointKind::Fixed);
  try {
    jointKind(spec, "hinge");
    FAIL() << "no exception for an unknown joint";
  } catch (const std::out_of_range& error) {
    EXPECT_NE(std::string(error.what()).find("'hinge'"), std::string::npos) << error.what();
  }
}
