// A Burger dropped from 0.2 m, as the training's roundTrack_simulation.launch spawns it,
// lands on its wheels and caster and comes to rest there, as it does in Gazebo.
//
// The robot below has the training fork's turtlebot3_burger.urdf.xacro figures (what
// matters for a landing): base_link's box 0.140 x 0.140 x 0.143 at x -0.032 z 0.070, mass
// 0.82573504 at base_link's origin; wheels r 0.033 l 0.018, mass 0.0285, at y +-0.08 z 0.023;
// the caster's box 0.030 x 0.009 x 0.020 at x -0.081 z -0.004 turned -1.57 about x, moved
// 1 mm along its own y (down once turned), mass 0.005 with inertia 0.001; base_scan's
// cylinder r 0.055 l 0.0315, mass 0.114 with inertia 0.001, at x -0.032 z 0.172; mu 0.1 on
// tyres and caster; the diff drive holding the wheels. The ground: Gazebo's ground_plane
// surface of the training's smallroundTrack.world, mu 100, mu2 50.
//
// Its centre of mass is 4 mm behind the axle and the caster's bottom 0.5 mm above the
// wheels' contact line, so the slightest pitch rate at the landing (1 rad/s) tips it over
// its wheels onto its face. With 10 solver iterations at the impact the robot left the
// ground pitching nose-down at 7.9 rad/s and lay on its face 0.3 s later.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "bullet_sim/simulation.h"

namespace {

using namespace bullet_sim;

const char* const kForkBurger = R"(<?xml version="1.0"?>
<robot name="turtlebot3_burger">
  <gazebo reference="wheel_left_link"><mu1>0.1</mu1><mu2>0.1</mu2><kp>500000.0</kp>
    <kd>10.0</kd><minDepth>0.001</minDepth><maxVel>0.1</maxVel></gazebo>
  <gazebo reference="wheel_right_link"><mu1>0.1</mu1><mu2>0.1</mu2><kp>500000.0</kp>
    <kd>10.0</kd><minDepth>0.001</minDepth><maxVel>0.1</maxVel></gazebo>
  <gazebo reference="caster_back_link"><mu1>0.1</mu1><mu2>0.1</mu2><kp>1000000.0</kp>
    <kd>100.0</kd><minDepth>0.001</minDepth><maxVel>1.0</maxVel></gazebo>
  <gazebo>
    <plugin name="controller" filename="libgazebo_ros_diff_drive.so">
      <leftJoint>wheel_left_joint</leftJoint><rightJoint>wheel_right_joint</rightJoint>
      <wheelSeparation>0.160</wheelSeparation><wheelDiameter>0.066</wheelDiameter>
      <wheelAcceleration>1</wheelAcceleration><wheelTorque>10</wheelTorque>
      <updateRate>30</updateRate><robotBaseFrame>base_footprint</robotBaseFrame>
    </plugin>
  </gazebo>
  <link name="base_footprint"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/><origin xyz="0 0 0.010"/>
  </joint>
  <link name="base_link">
    <collision><origin xyz="-0.032 0 0.070"/><geometry><box size="0.140 0.140 0.143"/></geometry></collision>
    <inertial><mass value="0.82573504"/>
      <inertia ixx="2.2124416e-03" ixy="-1.2294101e-05" ixz="3.4938785e-05" iyy="2.1193702e-03"
               iyz="-5.0120904e-06" izz="2.0064271e-03"/></inertial>
  </link>
  <joint name="wheel_left_joint" type="continuous">
    <parent link="base_link"/><child link="wheel_left_link"/>
    <origin xyz="0 0.08 0.023" rpy="-1.57 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <link name="wheel_left_link">
    <collision><geometry><cylinder length="0.018" radius="0.033"/></geometry></collision>
    <inertial><mass value="0.0284989"/>
      <inertia ixx="1.1175580e-05" ixy="0" ixz="0" iyy="1.1192413e-05" iyz="0" izz="2.0712558e-05"/></inertial>
  </link>
  <joint name="wheel_right_joint" type="continuous">
    <parent link="base_link"/><child link="wheel_right_link"/>
    <origin xyz="0 -0.08 0.023" rpy="-1.57 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <link name="wheel_right_link">
    <collision><geometry><cylinder length="0.018" radius="0.033"/></geometry></collision>
    <inertial><mass value="0.0284989"/>
      <inertia ixx="1.1175580e-05" ixy="0" ixz="0" iyy="1.1192413e-05" iyz="0" izz="2.0712558e-05"/></inertial>
  </link>
  <joint name="caster_back_joint" type="fixed">
    <parent link="base_link"/><child link="caster_back_link"/>
    <origin xyz="-0.081 0 -0.004" rpy="-1.57 0 0"/>
  </joint>
  <link name="caster_back_link">
    <collision><origin xyz="0 0.001 0"/><geometry><box size="0.030 0.009 0.020"/></geometry></collision>
    <inertial><mass value="0.005"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
  </link>
  <joint name="scan_joint" type="fixed">
    <parent link="base_link"/><child link="base_scan"/><origin xyz="-0.032 0 0.172"/>
  </joint>
  <link name="base_scan">
    <collision><origin xyz="0.015 0 -0.0065"/><geometry><cylinder length="0.0315" radius="0.055"/></geometry></collision>
    <inertial><mass value="0.114"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
  </link>
</robot>)";

const char* const kGround = R"(<sdf version="1.6"><world name="default">
  <model name="ground_plane"><static>1</static><link name="link">
    <collision name="collision"><geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
      <surface><friction><ode><mu>100</mu><mu2>50</mu2></ode></friction></surface></collision>
  </link></model>
</world></sdf>)";

// From the figures above, in base_footprint: the wheels' bottom is at
// 0.010 + 0.023 - 0.033 = 0; the caster's at 0.010 - 0.004 - 0.001 - 0.009 / 2 = 0.0005,
// 0.081 m behind the axle. Resting on both, base_footprint is on the ground, nose up by
// atan(0.0005 / 0.081) = 0.35 deg.
constexpr double kCasterGapM = 0.010 - 0.004 - 0.001 - 0.009 / 2;
constexpr double kCasterBehindM = 0.081;

double tiltDeg(const Pose3& pose) {
  const Eigen::Vector3d up = pose.orientation * Eigen::Vector3d::UnitZ();
  return std::acos(std::clamp(up.z(), -1.0, 1.0)) * 180 / M_PI;
}

struct Landing {
  double worst_tilt_deg = 0;
  Pose3 rest;
  Twist3 rest_twist;
};

/// Drops the fork's Burger from `z` with heading `yaw` and steps 2 s by hand.
Landing drop(double z, double yaw) {
  Simulation sim(loadWorldString(kGround, "ground.world"), SimConfig());
  Pose3 spawn;
  spawn.position.z() = z;
  spawn.orientation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  sim.spawnRobot("turtlebot3_burger", parseRobot(kForkBurger, "fork_burger.urdf"), spawn);
  Landing l;
  while (sim.timeS() < 2.0) {
    sim.step();
    l.worst_tilt_deg = std::max(l.worst_tilt_deg, tiltDeg(sim.modelPose("turtlebot3_burger")));
  }
  l.rest = sim.modelPose("turtlebot3_burger");
  l.rest_twist = sim.modelTwist("turtlebot3_burger");
  return l;
}

TEST(Drop, TrainingBurgerFromTwentyCentimetresLandsUprightOnWheelsAndCaster) {
  // The training's spawn: z 0.2, yaw 1.5675 (it hits the ground at sqrt(2 g 0.2) = 1.98 m/s).
  const Landing l = drop(0.2, 1.5675);
  // It never leans past 45 deg (the status line's TIPPED OVER); measured 9.6 deg.
  EXPECT_LT(l.worst_tilt_deg, 20.0);
  // At rest on wheels and caster: base_footprint on the ground, nose up by the caster's gap.
  const double resting_deg = std::atan2(kCasterGapM, kCasterBehindM) * 180 / M_PI;  // 0.35
  EXPECT_NEAR(tiltDeg(l.rest), resting_deg, 0.2);
  EXPECT_NEAR(l.rest.position.z(), 0.0, 0.001);
  // Where it was dropped (an inelastic landing, no bounce or hop away).
  EXPECT_LT(l.rest.position.head<2>().norm(), 0.01);
  EXPECT_LT(l.rest_twist.linear.norm(), 1e-3);
  EXPECT_LT(l.rest_twist.angular.norm(), 1e-2);
}

TEST(Drop, LandsUprightFromAnyHeightUpToHalfAMetre) {
  for (double z : {0.05, 0.1, 0.15, 0.3, 0.5}) {
    for (double yaw : {0.0, 1.5675}) {
      const Landing l = drop(z, yaw);
      EXPECT_LT(l.worst_tilt_deg, 20.0) << "from " << z << " m, yaw " << yaw;
      EXPECT_LT(tiltDeg(l.rest), 1.0) << "from " << z << " m, yaw " << yaw;
      EXPECT_NEAR(l.rest.position.z(), 0.0, 0.001) << "from " << z << " m, yaw " << yaw;
    }
  }
}

}  // namespace
