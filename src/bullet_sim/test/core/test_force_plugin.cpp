// libgazebo_ros_force.so: a wrench from a topic acts on a link at every step until the next
// message. A 2 kg box (izz = 2 (0.2^2 + 0.2^2) / 12 = 0.01333 kg m^2) floats without
// gravity: F = m a and tau = I alpha.
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
    "<gazebo><plugin name='push' filename='libgazebo_ros_force.so'>"
    "<bodyName>body</bodyName><topicName>force</topicName></plugin></gazebo>";

class ForcePlugin : public ::testing::Test {
 protected:
  ForcePlugin() : sim_(flatWorldWithGravity(0), SimConfig()) {
    Pose3 pose;
    pose.position = Eigen::Vector3d(0, 0, 1);
    sim_.spawnRobot("box", parseRobot(boxUrdf(2.0, kPlugin), "box"), pose);
  }
  Simulation sim_;
};

}  // namespace

TEST_F(ForcePlugin, TheWrenchActsAtEveryStepUntilTheNextOne) {
  Wrench push;
  push.force_n = Eigen::Vector3d(4, 0, 0);     // a = 4 / 2 = 2 m/s^2
  push.torque_nm = Eigen::Vector3d(0, 0, 0.1);  // alpha = 0.1 / 0.01333 = 7.5 rad/s^2
  sim_.setPluginWrench("box", 0, push);
  runFor(&sim_, 1.0);
  Twist3 v = sim_.modelTwist("box");
  EXPECT_NEAR(v.linear.x(), 2.0, 0.01);
  EXPECT_NEAR(v.angular.z(), 7.5, 0.04);
  EXPECT_NEAR(sim_.modelPose("box").position.x(), 1.0, 0.01);  // a t^2 / 2
  sim_.setPluginWrench("box", 0, Wrench());
  runFor(&sim_, 1.0);
  v = sim_.modelTwist("box");
  EXPECT_NEAR(v.linear.x(), 2.0, 0.01);  // no force: the speed stays
  EXPECT_NEAR(sim_.modelPose("box").position.x(), 3.0, 0.02);
}

TEST_F(ForcePlugin, AResetTakesTheWrenchAway) {
  Wrench push;
  push.force_n = Eigen::Vector3d(0, 4, 0);
  sim_.setPluginWrench("box", 0, push);
  runFor(&sim_, 0.1);
  sim_.reset();
  runFor(&sim_, 1.0);
  EXPECT_NEAR(sim_.modelTwist("box").linear.norm(), 0.0, 1e-9);
}

TEST(ForcePluginLoad, AMissingBodyIsALoadError) {
  Simulation sim(flatWorld(), SimConfig());
  const RobotSpec spec = parseRobot(
      boxUrdf(1, "<gazebo><plugin name='p' filename='libgazebo_ros_force.so'>"
                 "<bodyName>lid</bodyName><topicName>f</topicName></plugin></gazebo>"),
      "box");
  try {
    sim.spawnRobot("box", spec, Pose3());
    FAIL() << "spawned with a missing body";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()),
              "robot 'box': libgazebo_ros_force.so <bodyName> names link 'lid' that does "
              "not exist");
  }
}
