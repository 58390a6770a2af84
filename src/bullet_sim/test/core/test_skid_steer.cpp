// libgazebo_ros_skid_steer_drive.so on a four-wheeler (plugin_robots.h): wheel r 0.05 m,
// the plugin's wheelSeparation 0.35 m (the wheels' track). Expected values from the
// plugin's kinematics: a side's wheels turn at (v -+ w * separation / 2) / r.
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

const char* kPlugin =
    "<gazebo><plugin name='skid' filename='libgazebo_ros_skid_steer_drive.so'>"
    "<updateRate>100.0</updateRate>"
    "<leftFrontJoint>left_front_joint</leftFrontJoint>"
    "<rightFrontJoint>right_front_joint</rightFrontJoint>"
    "<leftRearJoint>left_rear_joint</leftRearJoint>"
    "<rightRearJoint>right_rear_joint</rightRearJoint>"
    "<wheelSeparation>0.35</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
    "<robotBaseFrame>base_link</robotBaseFrame><torque>20</torque>"
    "<commandTopic>drive</commandTopic><odometryTopic>wheel_odom</odometryTopic>"
    "<odometryFrame>odometry</odometryFrame><broadcastTF>true</broadcastTF>"
    "<covariance_x>0.002</covariance_x><covariance_y>0.003</covariance_y>"
    "<covariance_yaw>0.04</covariance_yaw></plugin></gazebo>";

double velocity(const JointStateData& js, const std::string& name) {
  for (size_t i = 0; i < js.names.size(); ++i) {
    if (js.names[i] == name) return js.velocities[i];
  }
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

class SkidSteer : public ::testing::Test {
 protected:
  SkidSteer() : sim_(flatWorld(), SimConfig()) {
    Pose3 spawn;
    spawn.position = Eigen::Vector3d(0, 0, 0.05);
    sim_.spawnRobot("car", parseRobot(fourWheelerUrdf(kPlugin), "car"), spawn);
    runFor(&sim_, 0.5);  // settle on the wheels
  }
  Simulation sim_;
};

}  // namespace

TEST(SkidSteerReader, TakesTheParametersAndGazebosDefaults) {
  const RobotSpec given = parseRobot(fourWheelerUrdf(kPlugin), "car");
  ASSERT_TRUE(given.diff_drive);
  const DiffDriveSpec& d = *given.diff_drive;
  EXPECT_EQ(d.plugin, "libgazebo_ros_skid_steer_drive.so");
  EXPECT_EQ(d.left_joint, "left_front_joint");
  EXPECT_EQ(d.right_rear_joint, "right_rear_joint");
  EXPECT_EQ(d.command_topic, "drive");
  EXPECT_EQ(d.odometry_topic, "wheel_odom");
  EXPECT_EQ(d.odometry_frame, "odometry");
  EXPECT_EQ(d.robot_base_frame, "base_link");
  EXPECT_DOUBLE_EQ(d.wheel_torque_nm, 20);
  EXPECT_TRUE(d.publish_odom_tf);
  ASSERT_TRUE(d.odometry_covariance_xy_yaw);
  EXPECT_DOUBLE_EQ(d.odometry_covariance_xy_yaw->z(), 0.04);

  const RobotSpec bare = parseRobot(
      fourWheelerUrdf("<gazebo><plugin name='s' filename='libgazebo_ros_skid_steer_drive.so'/>"
                      "</gazebo>"),
      "car");
  ASSERT_TRUE(bare.diff_drive);
  const DiffDriveSpec& b = *bare.diff_drive;
  EXPECT_EQ(b.left_joint, "left_front_joint");
  EXPECT_EQ(b.right_joint, "right_front_joint");
  EXPECT_EQ(b.left_rear_joint, "left_rear_joint");
  EXPECT_EQ(b.command_topic, "cmd_vel");
  EXPECT_EQ(b.odometry_topic, "odom");
  EXPECT_EQ(b.odometry_frame, "odom");
  EXPECT_EQ(b.robot_base_frame, "base_footprint");
  EXPECT_DOUBLE_EQ(b.wheel_separation_m, 0.4);
  EXPECT_DOUBLE_EQ(b.wheel_diameter_m, 0.15);
  EXPECT_DOUBLE_EQ(b.wheel_torque_nm, 5);
  EXPECT_DOUBLE_EQ(b.update_rate_hz, 100);
  EXPECT_DOUBLE_EQ(b.wheel_acceleration, 0);
  EXPECT_FALSE(b.publish_odom_tf);  // broadcastTF defaults to false
  EXPECT_EQ(*b.odometry_covariance_xy_yaw, Eigen::Vector3d(0.0001, 0.0001, 0.01));
}

TEST(SkidSteerReader, RefusesBadValuesAndMissingJointsNamingThem) {
  const std::string bad = fourWheelerUrdf(
      "<gazebo><plugin name='s' filename='libgazebo_ros_skid_steer_drive.so'>"
      "<wheelDiameter>-0.1</wheelDiameter></plugin></gazebo>");
  try {
    parseRobot(bad, "car");
    FAIL() << "a negative diameter loaded";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("<wheelDiameter>"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("-0.1"), std::string::npos) << e.what();
  }
  const RobotSpec missing = parseRobot(
      fourWheelerUrdf("<gazebo><plugin name='s' filename='libgazebo_ros_skid_steer_drive.so'>"
                      "<leftRearJoint>left_back_joint</leftRearJoint></plugin></gazebo>"),
      "car");
  Simulation sim(flatWorld(), SimConfig());
  try {
    sim.spawnRobot("car", missing, Pose3());
    FAIL() << "a missing joint loaded";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()),
              "robot 'car': libgazebo_ros_skid_steer_drive.so <leftRearJoint> names joint "
              "'left_back_joint' that does not exist (or is not revolute/continuous)");
  }
}

TEST_F(SkidSteer, DrivesStraightAtTheCommandedSpeedWithAllFourWheels) {
  sim_.setCmdVel("car", 0.3, 0);
  runFor(&sim_, 1.0);  // up to speed
  const Pose3 start = sim_.modelPose("car");
  runFor(&sim_, 2.0);
  const Pose3 end = sim_.modelPose("car");
  // 0.3 m/s for 2 s: 0.6 m along x, within 2 % (the wheels' rolling without slip).
  EXPECT_NEAR(end.position.x() - start.position.x(), 0.6, 0.012);
  EXPECT_NEAR(end.position.y(), 0, 0.005);
  EXPECT_NEAR(yawOf(end.orientation), 0, 0.01);
  // Every wheel at v / r = 0.3 / 0.05 = 6 rad/s.
  const JointStateData js = sim_.readJointStates("car");
  for (const char* joint :
       {"left_front_joint", "right_front_joint", "left_rear_joint", "right_rear_joint"}) {
    EXPECT_NEAR(velocity(js, joint), 6.0, 0.06) << joint;
  }
}

TEST_F(SkidSteer, TurnsInPlaceCounterClockwiseSlippingNoFasterThanCommanded) {
  sim_.setCmdVel("car", 0, 1.0);
  runFor(&sim_, 0.5);
  // Left wheels at -w * 0.35 / 2 / r = -3.5 rad/s, right ones at +3.5 rad/s.
  const JointStateData js = sim_.readJointStates("car");
  EXPECT_NEAR(velocity(js, "left_front_joint"), -3.5, 0.05);
  EXPECT_NEAR(velocity(js, "left_rear_joint"), -3.5, 0.05);
  EXPECT_NEAR(velocity(js, "right_front_joint"), 3.5, 0.05);
  EXPECT_NEAR(velocity(js, "right_rear_joint"), 3.5, 0.05);
  // The wheels slip sideways (they sit 0.12 m ahead of and behind the turn's centre), so
  // the body turns slower than the 1 rad/s rolling alone would give, never faster; and
  // about its middle.
  const double turned = turnFor(&sim_, "car", 2.0);
  EXPECT_GT(turned, 0.5);
  EXPECT_LE(turned, 2.0 * 1.02);
  EXPECT_LT(sim_.modelPose("car").position.head<2>().norm(), 0.03);
}

TEST_F(SkidSteer, OdometryIsTheWorldPoseWithThePluginsCovariance) {
  sim_.setCmdVel("car", 0.2, 0.5);
  runFor(&sim_, 2.0);
  const OdometryData odom = sim_.readOdometry("car");
  const Pose3 world = sim_.modelPose("car");
  EXPECT_EQ(odom.frame_id, "odometry");
  EXPECT_EQ(odom.child_frame_id, "base_link");
  EXPECT_LT((odom.pose.position - world.position).norm(), 1e-9);
  EXPECT_LT(odom.pose.orientation.angularDistance(world.orientation), 1e-9);
  const double diagonal[6] = {0.002, 0.003, 1e12, 1e12, 1e12, 0.04};
  for (int i = 0; i < 36; ++i) {
    const double expected = i % 7 == 0 ? diagonal[i / 7] : 0.0;
    EXPECT_EQ(odom.pose_covariance[i], expected) << i;
    EXPECT_EQ(odom.twist_covariance[i], expected) << i;
  }
  // Forward speed in the body frame: the command's 0.2 m/s, within the turn's slip.
  EXPECT_NEAR(odom.twist_in_child.linear.x(), 0.2, 0.02);
}
