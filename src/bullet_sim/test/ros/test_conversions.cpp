// The node's adapters between core data and ROS messages (no master needed).
#include "topics/conversions.h"
#include "topics/tf_prefix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bullet_sim_node {
namespace {

TEST(Conversions, PoseRoundTripKeepsPositionAndYaw) {
  bullet_sim::Pose3 pose;
  pose.position = {1.5, -2.0, 0.25};
  pose.orientation = Eigen::AngleAxisd(1.5675, Eigen::Vector3d::UnitZ());
  const geometry_msgs::Pose msg = toMsg(pose);
  EXPECT_DOUBLE_EQ(msg.position.x, 1.5);
  EXPECT_DOUBLE_EQ(msg.orientation.z, std::sin(1.5675 / 2));
  EXPECT_DOUBLE_EQ(msg.orientation.w, std::cos(1.5675 / 2));
  const bullet_sim::Pose3 back = fromMsg(msg);
  EXPECT_TRUE(back.position.isApprox(pose.position));
  EXPECT_NEAR(back.orientation.angularDistance(pose.orientation), 0.0, 1e-12);
}

TEST(Conversions, UnsetOrientationBecomesIdentityAndOthersAreNormalised) {
  geometry_msgs::Pose msg;  // all-zero quaternion, as an unfilled request sends it
  EXPECT_TRUE(fromMsg(msg).orientation.isApprox(Eigen::Quaterniond::Identity()));
  msg.orientation.w = 2.0;
  EXPECT_DOUBLE_EQ(fromMsg(msg).orientation.norm(), 1.0);
}

TEST(Conversions, ScanKeepsLayoutStampAndInfinity) {
  bullet_sim::LaserScanData scan;
  scan.time_s = 12.25;
  scan.frame_id = "base_scan";
  scan.angle_min = 0;
  scan.angle_max = 6.28319;
  scan.angle_increment = 6.28319 / 360;
  scan.range_min = 0.12;
  scan.range_max = 3.5;
  scan.ranges = {0.5f, std::numeric_limits<float>::infinity()};
  const sensor_msgs::LaserScan msg = toMsg(scan);
  EXPECT_EQ(msg.header.stamp, ros::Time(12, 250000000));
  EXPECT_EQ(msg.header.frame_id, "base_scan");
  EXPECT_FLOAT_EQ(msg.range_min, 0.12f);
  ASSERT_EQ(msg.ranges.size(), 2u);
  EXPECT_TRUE(std::isinf(msg.ranges[1]));
}

TEST(Conversions, ImuCovariancesOnTheDiagonal) {
  bullet_sim::ImuData imu;
  imu.frame_id = "imu_link";
  imu.linear_acceleration = {0, 0, 9.8};
  imu.angular_velocity_cov = 4e-4;
  const sensor_msgs::Imu msg = toMsg(imu);
  EXPECT_DOUBLE_EQ(msg.linear_acceleration.z, 9.8);
  EXPECT_DOUBLE_EQ(msg.angular_velocity_covariance[0], 4e-4);
  EXPECT_DOUBLE_EQ(msg.angular_velocity_covariance[4], 4e-4);
  EXPECT_DOUBLE_EQ(msg.angular_velocity_covariance[8], 4e-4);
  EXPECT_DOUBLE_EQ(msg.angular_velocity_covariance[1], 0.0);
}

TEST(Conversions, OdometryAndItsTransformAgree) {
  bullet_sim::OdometryData odom;
  odom.time_s = 3.5;
  odom.frame_id = "odom";
  odom.child_frame_id = "base_footprint";
  odom.pose.position = {0.2, 1.0, 0.0};
  odom.pose.orientation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  odom.twist_in_child.linear = {0.2, 0, 0};
  const nav_msgs::Odometry msg = toMsg(odom);
  const geometry_msgs::TransformStamped tf = toTransformMsg(odom);
  EXPECT_EQ(msg.child_frame_id, tf.child_frame_id);
  EXPECT_EQ(msg.header.stamp, tf.header.stamp);
  EXPECT_DOUBLE_EQ(msg.pose.pose.position.y, tf.transform.translation.y);
  EXPECT_DOUBLE_EQ(msg.pose.pose.orientation.z, tf.transform.rotation.z);
  EXPECT_DOUBLE_EQ(msg.twist.twist.linear.x, 0.2);
}

TEST(Conversions, JointStatesKeepNamesInOrder) {
  bullet_sim::JointStateData joints;
  joints.names = {"flag_pole_joint", "wheel_left_joint", "wheel_right_joint"};
  joints.positions = {0.1, 0.2, 0.3};
  joints.velocities = {0, 1, 2};
  joints.efforts = {0, 0, 0};
  const sensor_msgs::JointState msg = toMsg(joints);
  EXPECT_EQ(msg.name, joints.names);
  EXPECT_EQ(msg.position, joints.positions);
  EXPECT_EQ(msg.velocity, joints.velocities);
}

TEST(Conversions, FirstNonFiniteFieldIsNamed) {
  geometry_msgs::Pose pose;
  pose.orientation.w = 1;
  EXPECT_FALSE(firstNonFinite(pose));
  pose.orientation.z = std::numeric_limits<double>::quiet_NaN();
  ASSERT_TRUE(firstNonFinite(pose));
  EXPECT_EQ(firstNonFinite(pose)->rfind("orientation.z = ", 0), 0u) << *firstNonFinite(pose);
  geometry_msgs::Twist twist;
  twist.angular.y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(*firstNonFinite(twist), "angular.y = inf");
}

TEST(TfPrefix, FramesGoUnderThePrefixAsTfResolveDoes) {
  EXPECT_EQ(resolveFrame("tb3_1", "odom"), "tb3_1/odom");
  EXPECT_EQ(resolveFrame("/tb3_1", "base_scan"), "tb3_1/base_scan");
  EXPECT_EQ(resolveFrame("", "odom"), "odom");
  EXPECT_EQ(resolveFrame("tb3_1", "/map"), "map");
  EXPECT_EQ(resolveFrame("a/b", "imu_link"), "a/b/imu_link");
}

}  // namespace
}  // namespace bullet_sim_node
