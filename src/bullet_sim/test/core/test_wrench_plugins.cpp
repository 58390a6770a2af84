// libgazebo_ros_ft_sensor.so and libgazebo_ros_f3d.so against wrenches worked out by hand.
// The ft_sensor reads what the child exerts on its joint (Gazebo's body2 wrench: the
// opposite of the joint's pull on the child), in the child link's frame, torque about the
// joint: a 2 kg bob hanging at rest (g = 9.8) reads -m g = -19.6 N along the world's up,
// turned into its frame. The f3d reads what is pushed on its link from outside, in world
// axes: not gravity, not contacts.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "load_errors.h"
#include "plugin_robots.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

constexpr double kMassKg = 2.0, kG = 9.8;

std::string ftSensor(const std::string& body) {
  return "<gazebo><plugin name='ft' filename='libgazebo_ros_ft_sensor.so'>" + body +
         "</plugin></gazebo>";
}

std::string f3d(const std::string& body) {
  return "<gazebo><plugin name='f3d' filename='libgazebo_ros_f3d.so'>" + body +
         "</plugin></gazebo>";
}

const std::string kHingeFt = ftSensor("<jointName>hinge</jointName><topicName>ft</topicName>");

/// A pendulum robot "p" standing on the ground of `sim`, left 1 s to settle.
void spawnPendulum(Simulation* sim, const std::string& rpy, const std::string& com,
                   const std::string& gazebo) {
  Pose3 pose;
  pose.position = Eigen::Vector3d(0, 0, 0.05);
  sim->spawnRobot("p", parseRobot(hangingLinkUrdf(rpy, com, gazebo), "pendulum"), pose);
  runFor(sim, 1.0);
}

void expectNear(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tol) << "component " << i;
}

}  // namespace

TEST(FtSensor, AHangingBobPullsItsJointDownWithItsWeight) {
  Simulation sim(flatWorldWithGravity(-kG), SimConfig());
  spawnPendulum(&sim, "0 0 0", "0 0 -0.5", kHingeFt);
  const WrenchData ft = sim.readForceTorque("p", 0);
  EXPECT_EQ(ft.frame_id, "bob");
  expectNear(ft.force_n, Eigen::Vector3d(0, 0, -kMassKg * kG), 0.02);
  expectNear(ft.torque_nm, Eigen::Vector3d::Zero(), 0.005);
}

TEST(FtSensor, ATiltedJointFrameTurnsTheReading) {
  // The joint frame rolled 0.5 rad about x; the centre of mass 0.5 m straight below the
  // joint, i.e. at -0.5 (0, sin 0.5, cos 0.5) in bob's frame. The weight's line in bob's
  // frame is R^T z = (0, sin 0.5, cos 0.5).
  const double s = std::sin(0.5), c = std::cos(0.5);
  const std::string com = "0 " + std::to_string(-0.5 * s) + " " + std::to_string(-0.5 * c);
  Simulation sim(flatWorldWithGravity(-kG), SimConfig());
  spawnPendulum(&sim, "0.5 0 0", com, kHingeFt);
  const WrenchData ft = sim.readForceTorque("p", 0);
  expectNear(ft.force_n, -kMassKg * kG * Eigen::Vector3d(0, s, c), 0.02);
  expectNear(ft.torque_nm, Eigen::Vector3d::Zero(), 0.005);
}

TEST(FtSensor, AnOffsetCentreOfMassLoadsTheJointWithMgd) {
  // The centre of mass 0.1 m along x from the line below the joint (the hinge turns about
  // x, so the bob hangs still): gravity's moment about the joint is
  // (0.1, 0, -0.5) x (0, 0, -m g) = (0, 0.1 m g, 0); the joint holds it with the
  // opposite, and the child exerts +0.1 m g = 1.96 N m about y on the joint.
  Simulation sim(flatWorldWithGravity(-kG), SimConfig());
  spawnPendulum(&sim, "0 0 0", "0.1 0 -0.5", kHingeFt);
  const WrenchData ft = sim.readForceTorque("p", 0);
  expectNear(ft.force_n, Eigen::Vector3d(0, 0, -kMassKg * kG), 0.02);
  expectNear(ft.torque_nm, Eigen::Vector3d(0, 0.1 * kMassKg * kG, 0), 0.005);
}

TEST(FtSensor, AnEffortOnTheJointIsInTheReading) {
  // A free hinge passes no torque about its axis but the effort applied to it: the child
  // exerts -0.5 N m about x on the joint while the effort turns it.
  Simulation sim(flatWorldWithGravity(-kG), SimConfig());
  spawnPendulum(&sim, "0 0 0", "0 0 -0.5", kHingeFt);
  JointEffort effort;
  effort.robot = "p";
  effort.joint = "hinge";
  effort.effort = 0.5;
  effort.window.duration_s = -1;
  sim.externalForces().addEffort(effort, sim.timeS());
  runFor(&sim, 0.05);
  EXPECT_NEAR(sim.readForceTorque("p", 0).torque_nm.x(), -0.5, 0.01);
}

TEST(FtSensor, NoiseIsSeededAndHasTheGivenDeviation) {
  const std::string noisy = ftSensor(
      "<jointName>hinge</jointName><topicName>ft</topicName><gaussianNoise>0.5</gaussianNoise>");
  auto readings = [&](uint64_t seed) {
    SimConfig cfg;
    cfg.seed = seed;
    Simulation sim(flatWorldWithGravity(-kG), cfg);
    spawnPendulum(&sim, "0 0 0", "0 0 -0.5", noisy);
    std::vector<double> fz;
    for (int i = 0; i < 4000; ++i) fz.push_back(sim.readForceTorque("p", 0).force_n.z());
    return fz;
  };
  const std::vector<double> a = readings(7), b = readings(7), c = readings(8);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double mean = 0, var = 0;
  for (double v : a) mean += v / a.size();
  for (double v : a) var += (v - mean) * (v - mean) / (a.size() - 1);
  EXPECT_NEAR(mean, -kMassKg * kG, 0.03);  // sd of the mean 0.5 / sqrt(4000) = 0.008
  EXPECT_NEAR(std::sqrt(var), 0.5, 0.02);  // sd of the sd ~ 0.5 / sqrt(8000) = 0.006
}

TEST(FtSensor, IsDueAtItsUpdateRateOrEveryStep) {
  for (const auto& [rate, expected] : {std::pair<std::string, int>{"", 1000}, {"50", 50}}) {
    Simulation sim(flatWorldWithGravity(-kG), SimConfig());
    const std::string body = "<jointName>hinge</jointName><topicName>ft</topicName>" +
                             (rate.empty() ? "" : "<updateRate>" + rate + "</updateRate>");
    spawnPendulum(&sim, "0 0 0", "0 0 -0.5", ftSensor(body));
    int due = 0;
    for (int k = 0; k < 1000; ++k) {
      for (const DueSensor& d : sim.step()) due += d.kind == SensorKind::ForceTorque;
    }
    EXPECT_EQ(due, expected) << "updateRate '" << rate << "'";
  }
}

TEST(FtSensorLoad, BadValuesAndUnknownJointsAreLoadErrors) {
  auto parse = [](const std::string& body) {
    return [body] { parseRobot(hangingLinkUrdf("0 0 0", "0 0 -0.5", ftSensor(body)), "p"); };
  };
  const std::string rate = loadErrorOf(
      parse("<jointName>hinge</jointName><topicName>ft</topicName><updateRate>fast</updateRate>"));
  EXPECT_NE(rate.find("<updateRate>"), std::string::npos) << rate;
  EXPECT_NE(rate.find("'fast'"), std::string::npos) << rate;
  EXPECT_NE(rate.find("libgazebo_ros_ft_sensor.so"), std::string::npos) << rate;
  const std::string noise = loadErrorOf(parse(
      "<jointName>hinge</jointName><topicName>ft</topicName><gaussianNoise>-1</gaussianNoise>"));
  EXPECT_NE(noise.find("<gaussianNoise>"), std::string::npos) << noise;
  EXPECT_NE(loadErrorOf(parse("<topicName>ft</topicName>")).find("<jointName> is missing"),
            std::string::npos);
  Simulation sim(flatWorld(), SimConfig());
  const RobotSpec spec = parseRobot(
      hangingLinkUrdf("0 0 0", "0 0 -0.5",
                      ftSensor("<jointName>wrist</jointName><topicName>ft</topicName>")),
      "p");
  EXPECT_EQ(loadErrorOf([&] { sim.spawnRobot("p", spec, Pose3()); }),
            "robot 'p': libgazebo_ros_ft_sensor.so <jointName> names joint 'wrist' that does "
            "not exist (or is not revolute/continuous: a fixed joint's links are one body, as "
            "Gazebo lumps them)");
}

namespace {

/// A 2 kg box with a force plugin (topic "force") and an f3d (frame `frame`) on it.
void spawnBoxWithF3d(Simulation* sim, double z, const std::string& frame) {
  const std::string plugins =
      "<gazebo><plugin name='push' filename='libgazebo_ros_force.so'><bodyName>body"
      "</bodyName><topicName>force</topicName></plugin></gazebo>" +
      f3d("<bodyName>body</bodyName><topicName>f3d</topicName>" +
          (frame.empty() ? "" : "<frameName>" + frame + "</frameName>"));
  Pose3 pose;
  pose.position = Eigen::Vector3d(0, 0, z);
  sim->spawnRobot("box", parseRobot(boxUrdf(kMassKg, plugins), "box"), pose);
}

}  // namespace

TEST(F3d, ReadsThePushedWrenchInWorldAxesWhateverItsFrame) {
  // The torque turns the box 3.75 rad about z in 1 s; the reading stays in world axes.
  Simulation sim(flatWorldWithGravity(0), SimConfig());
  spawnBoxWithF3d(&sim, 1.0, "body");
  Wrench push;
  push.force_n = Eigen::Vector3d(4, 0, 0);
  push.torque_nm = Eigen::Vector3d(0, 0, 0.1);
  sim.setPluginWrench("box", 0, push);
  runFor(&sim, 1.0);
  const WrenchData reading = sim.readF3d("box", 0);
  EXPECT_EQ(reading.frame_id, "body");
  expectNear(reading.force_n, push.force_n, 1e-12);
  expectNear(reading.torque_nm, push.torque_nm, 1e-12);
  EXPECT_NEAR(reading.time_s, 1.0, 1e-9);
}

TEST(F3d, AddsTheServicesWrenchesAndLeavesOutGravityAndContacts) {
  // A box resting on the ground: its weight and the ground's push are not in the reading;
  // a force plugin's wrench and an apply_body_wrench add up.
  Simulation sim(flatWorldWithGravity(-kG), SimConfig());
  spawnBoxWithF3d(&sim, 0.1, "");
  runFor(&sim, 0.5);
  WrenchData reading = sim.readF3d("box", 0);
  EXPECT_EQ(reading.frame_id, "world");
  expectNear(reading.force_n, Eigen::Vector3d::Zero(), 1e-12);
  Wrench push;
  push.force_n = Eigen::Vector3d(0, 0, 5);
  sim.setPluginWrench("box", 0, push);
  BodyWrench service;
  service.robot = "box";
  service.link = "body";
  service.wrench.force_n = Eigen::Vector3d(1, 2, 0);
  service.wrench.torque_nm = Eigen::Vector3d(0, 0, 0.3);
  service.window.duration_s = -1;
  sim.externalForces().addWrench(service, sim.timeS());
  runFor(&sim, 0.01);
  reading = sim.readF3d("box", 0);
  expectNear(reading.force_n, Eigen::Vector3d(1, 2, 5), 1e-12);
  expectNear(reading.torque_nm, Eigen::Vector3d(0, 0, 0.3), 1e-12);
}

TEST(F3dLoad, MissingOrUnknownBodyIsALoadError) {
  const std::string missing =
      loadErrorOf([] { parseRobot(boxUrdf(1, f3d("<topicName>t</topicName>")), "box"); });
  EXPECT_EQ(missing,
            "box: <plugin name=\"f3d\" filename=\"libgazebo_ros_f3d.so\">: <bodyName> is missing");
  Simulation sim(flatWorld(), SimConfig());
  const RobotSpec spec =
      parseRobot(boxUrdf(1, f3d("<bodyName>lid</bodyName><topicName>t</topicName>")), "box");
  EXPECT_EQ(loadErrorOf([&] { sim.spawnRobot("box", spec, Pose3()); }),
            "robot 'box': libgazebo_ros_f3d.so <bodyName> names link 'lid' that does not "
            "exist");
}
