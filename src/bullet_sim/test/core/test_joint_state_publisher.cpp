// libgazebo_ros_joint_state_publisher.so on the four-wheeler (plugin_robots.h): the joints
// it names, in its order, at its rate, in place of the joint states of every joint.
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "plugin_robots.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

std::string publisher(const std::string& inside) {
  return "<gazebo><plugin name='joints' filename='libgazebo_ros_joint_state_publisher.so'>" +
         inside + "</plugin></gazebo>";
}

const std::string kWhere =
    "car: <plugin name=\"joints\" filename=\"libgazebo_ros_joint_state_publisher.so\">";

std::string loadError(const std::string& inside) {
  try {
    parseRobot(fourWheelerUrdf(publisher(inside)), "car");
  } catch (const LoadError& e) {
    return e.what();
  }
  return "loaded";
}

/// Counts the joint-state readings due in 1 s of 1 ms steps: [0] every joint's, [1] the
/// first plugin's, [2] the second's.
std::array<int, 3> dueInOneSecond(Simulation* sim) {
  std::array<int, 3> due{};
  for (int k = 0; k < 1000; ++k) {
    for (const DueSensor& d : sim->step()) {
      if (d.kind == SensorKind::JointStates) ++due[0];
      if (d.kind == SensorKind::PluginJointStates) ++due[1 + d.index];
    }
  }
  return due;
}

}  // namespace

TEST(JointStatePublisherReader, SplitsTheJointListAndTakesTheRate) {
  const RobotSpec spec = parseRobot(
      fourWheelerUrdf(publisher("<jointName>right_rear_joint, left_front_joint,\n"
                                "  left_rear_joint</jointName><updateRate>50</updateRate>")),
      "car");
  ASSERT_EQ(spec.joint_state_publishers.size(), 1u);
  const JointStatePublisherSpec& p = spec.joint_state_publishers[0];
  EXPECT_EQ(p.joints,
            (std::vector<std::string>{"right_rear_joint", "left_front_joint", "left_rear_joint"}));
  EXPECT_DOUBLE_EQ(p.update_rate_hz, 50);
  const RobotSpec bare =
      parseRobot(fourWheelerUrdf(publisher("<jointName>left_front_joint</jointName>")), "car");
  EXPECT_DOUBLE_EQ(bare.joint_state_publishers.at(0).update_rate_hz, 100);  // the default
}

TEST(JointStatePublisherReader, WithoutAJointListItPublishesNoJointsAndSaysSo) {
  const RobotSpec spec = parseRobot(fourWheelerUrdf(publisher("")), "car");
  ASSERT_EQ(spec.joint_state_publishers.size(), 1u);
  EXPECT_TRUE(spec.joint_state_publishers[0].joints.empty());
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0], kWhere.substr(5) +
                                  ": no <jointName>: as in Gazebo, joint_states carries no joints");
}

TEST(JointStatePublisherReader, RefusesBadValuesNamingThePluginTheElementAndTheValue) {
  EXPECT_EQ(loadError("<jointName>left_front_joint, left_back_joint</jointName>"),
            kWhere + " <jointName>: the model has no joint 'left_back_joint'");
  EXPECT_EQ(loadError("<jointName>left_front_joint,,left_rear_joint</jointName>"),
            kWhere + " <jointName>: 'left_front_joint,,left_rear_joint' has an empty name");
  EXPECT_EQ(loadError("<jointName></jointName>"), kWhere + " <jointName>: '' has an empty name");
  EXPECT_EQ(loadError("<jointName>left_front_joint</jointName><updateRate>fast</updateRate>"),
            kWhere + " <updateRate>: 'fast' is not a number");
  EXPECT_EQ(loadError("<jointName>left_front_joint</jointName><updateRate>-10</updateRate>"),
            kWhere + " <updateRate>: '-10' is not a rate >= 0 Hz");
}

TEST(JointStatePublisher, AFixedJointIsALoadErrorAtTheSpawn) {
  const std::string urdf =
      "<robot name='post'><link name='base'><inertial><mass value='1'/><inertia ixx='0.1' "
      "ixy='0' ixz='0' iyy='0.1' iyz='0' izz='0.1'/></inertial></link><link name='top'>"
      "<inertial><mass value='1'/><inertia ixx='0.1' ixy='0' ixz='0' iyy='0.1' iyz='0' "
      "izz='0.1'/></inertial></link><joint name='weld' type='fixed'><parent link='base'/>"
      "<child link='top'/></joint>" +
      publisher("<jointName>weld</jointName>") + "</robot>";
  Simulation sim(flatWorld(), SimConfig());
  try {
    sim.spawnRobot("post", parseRobot(urdf, "post"), Pose3());
    FAIL() << "spawned";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()),
              "robot 'post': libgazebo_ros_joint_state_publisher.so <jointName> names joint "
              "'weld' that does not move here (only revolute and continuous joints of a "
              "movable model do)");
  }
}

TEST(JointStatePublisher, PublishesItsJointsInItsOrder) {
  Simulation sim(flatWorld(), SimConfig());
  Pose3 spawn;
  spawn.position = Eigen::Vector3d(0, 0, 0.05);
  sim.spawnRobot(
      "car",
      parseRobot(fourWheelerUrdf(publisher("<jointName>right_rear_joint, left_front_joint"
                                           "</jointName>")),
                 "car"),
      spawn);
  sim.setJointPositions("car", {{"left_front_joint", 0.3}, {"right_rear_joint", -1.2},
                                {"left_rear_joint", 2.0}});
  const JointStateData js = sim.readPluginJointStates("car", 0);
  EXPECT_EQ(js.names, (std::vector<std::string>{"right_rear_joint", "left_front_joint"}));
  ASSERT_EQ(js.positions.size(), 2u);
  EXPECT_NEAR(js.positions[0], -1.2, 1e-9);
  EXPECT_NEAR(js.positions[1], 0.3, 1e-9);
  EXPECT_EQ(js.velocities, (std::vector<double>{0.0, 0.0}));  // at rest after the set
  EXPECT_TRUE(js.efforts.empty());  // Gazebo's message has none either
}

TEST(JointStatePublisher, ReadsTheWheelSpeedsOfADrive) {
  // A skid steer driving at 0.3 m/s turns every wheel (r 0.05 m) at 6 rad/s.
  Simulation sim(flatWorld(), SimConfig());
  Pose3 spawn;
  spawn.position = Eigen::Vector3d(0, 0, 0.05);
  const std::string plugins =
      "<gazebo><plugin name='skid' filename='libgazebo_ros_skid_steer_drive.so'>"
      "<wheelSeparation>0.35</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
      "<torque>20</torque></plugin>"
      "<plugin name='joints' filename='libgazebo_ros_joint_state_publisher.so'>"
      "<jointName>left_rear_joint,right_front_joint</jointName></plugin></gazebo>";
  sim.spawnRobot("car", parseRobot(fourWheelerUrdf(plugins), "car"), spawn);
  runFor(&sim, 0.5);
  sim.setCmdVel("car", 0.3, 0);
  runFor(&sim, 1.5);
  const JointStateData js = sim.readPluginJointStates("car", 0);
  ASSERT_EQ(js.velocities.size(), 2u);
  EXPECT_NEAR(js.velocities[0], 6.0, 0.06);
  EXPECT_NEAR(js.velocities[1], 6.0, 0.06);
  EXPECT_DOUBLE_EQ(js.velocities[0], sim.jointVelocity("car", "left_rear_joint"));
  EXPECT_DOUBLE_EQ(js.positions[1], sim.jointPosition("car", "right_front_joint"));
}

TEST(JointStatePublisher, TakesThePlaceOfEveryJointsStatesAtItsOwnRate) {
  Simulation without(flatWorld(), SimConfig());
  without.spawnRobot("car", parseRobot(fourWheelerUrdf(""), "car"), Pose3());
  EXPECT_EQ(dueInOneSecond(&without), (std::array<int, 3>{30, 0, 0}));  // every joint, 30 Hz

  Simulation with(flatWorld(), SimConfig());
  const std::string two =
      publisher("<jointName>left_front_joint</jointName><updateRate>50</updateRate>") +
      "<gazebo><plugin name='more' filename='libgazebo_ros_joint_state_publisher.so'>"
      "<jointName>right_front_joint</jointName></plugin></gazebo>";
  with.spawnRobot("car", parseRobot(fourWheelerUrdf(two), "car"), Pose3());
  EXPECT_EQ(dueInOneSecond(&with), (std::array<int, 3>{0, 50, 100}));
}

TEST(JointStatePublisherReader, ReadsBothPluginsOfAnSdfModelAlike) {
  const std::string inertial =
      "<inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz>"
      "</inertia></inertial>";
  const auto sdf = [&](const std::string& joint_names) {
    return "<sdf version='1.6'><model name='arm'><link name='base'>" + inertial +
           "</link><link name='upper'>" + inertial +
           "</link><joint name='shoulder' type='revolute'><parent>base</parent>"
           "<child>upper</child><axis><xyz>0 0 1</xyz></axis></joint>"
           "<plugin name='joints' filename='libgazebo_ros_joint_state_publisher.so'>"
           "<jointName>" + joint_names + "</jointName><updateRate>10</updateRate></plugin>"
           "<plugin name='move' filename='libgazebo_ros_planar_move.so'>"
           "<odometryRate>5</odometryRate></plugin></model></sdf>";
  };
  const RobotSpec spec = parseSdfModelString(sdf("shoulder"), "arm.sdf");
  ASSERT_EQ(spec.joint_state_publishers.size(), 1u);
  EXPECT_EQ(spec.joint_state_publishers[0].joints, std::vector<std::string>{"shoulder"});
  EXPECT_DOUBLE_EQ(spec.joint_state_publishers[0].update_rate_hz, 10);
  ASSERT_TRUE(spec.planar_move);
  EXPECT_DOUBLE_EQ(spec.planar_move->odometry_rate_hz, 5);
  try {
    parseSdfModelString(sdf("elbow"), "arm.sdf");
    FAIL() << "loaded with an unknown joint";
  } catch (const LoadError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find("arm.sdf: "), 0u) << message;
    EXPECT_NE(message.find("<plugin name=\"joints\" filename=\"libgazebo_ros_joint_state_"
                           "publisher.so\"> <jointName>: the model has no joint 'elbow'"),
              std::string::npos)
        << message;
  }
}
