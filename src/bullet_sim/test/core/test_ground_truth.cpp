// libgazebo_ros_p3d.so: the ground truth of a link. A 1 kg box floating in a world without
// gravity is given a velocity and moves exactly by it; the plugin's offsets, frames, noise
// and rate are then worked out by hand.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "plugin_robots.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

std::string p3d(const std::string& inside) {
  return "<gazebo><plugin name='truth' filename='libgazebo_ros_p3d.so'>" + inside +
         "</plugin></gazebo>";
}

/// The box spawned at (0, 0, 1), moving at 0.5 m/s along x and turning at 0.2 rad/s.
void spawnMovingBox(Simulation* sim, const std::string& plugin) {
  Pose3 pose;
  pose.position = Eigen::Vector3d(0, 0, 1);
  sim->spawnRobot("box", parseRobot(boxUrdf(1.0, plugin), "box"), pose);
  Twist3 twist;
  twist.linear = Eigen::Vector3d(0.5, 0, 0);
  twist.angular = Eigen::Vector3d(0, 0, 0.2);
  sim->setModelState("box", pose, twist);
}

}  // namespace

TEST(GroundTruth, IsTheBodysWorldPoseWithTheOffsetsAndItsWorldVelocity) {
  Simulation sim(flatWorldWithGravity(0), SimConfig());
  spawnMovingBox(&sim, p3d("<bodyName>body</bodyName><topicName>truth</topicName>"
                           "<xyzOffset>1 2 3</xyzOffset><rpyOffset>0 0 0.5</rpyOffset>"));
  runFor(&sim, 2.0);
  const OdometryData truth = sim.readGroundTruth("box", 0);
  EXPECT_EQ(truth.frame_id, "world");
  EXPECT_EQ(truth.child_frame_id, "body");
  // After 2 s: x = 0.5 * 2 = 1 m, yaw 0.2 * 2 = 0.4 rad; plus the offsets (1, 2, 3) and
  // a turn of 0.5 rad about z.
  EXPECT_NEAR(truth.pose.position.x(), 2.0, 1e-3);
  EXPECT_NEAR(truth.pose.position.y(), 2.0, 1e-3);
  EXPECT_NEAR(truth.pose.position.z(), 4.0, 1e-3);
  EXPECT_NEAR(yawOf(truth.pose.orientation), 0.9, 1e-3);
  EXPECT_NEAR(truth.twist_in_child.linear.x(), 0.5, 1e-6);
  EXPECT_NEAR(truth.twist_in_child.angular.z(), 0.2, 1e-6);
  for (double c : truth.pose_covariance) EXPECT_EQ(c, 0.0);
}

TEST(GroundTruth, RelativeToALinkOfTheModel) {
  Simulation sim(flatWorld(), SimConfig());
  Pose3 spawn;
  spawn.position = Eigen::Vector3d(3, 4, 0.05);
  spawn.orientation = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
  sim.spawnRobot("car",
                 parseRobot(fourWheelerUrdf(p3d("<bodyName>left_front_link</bodyName>"
                                                "<topicName>wheel</topicName>"
                                                "<frameName>base_link</frameName>")),
                            "car"),
                 spawn);
  runFor(&sim, 0.5);
  const OdometryData truth = sim.readGroundTruth("car", 0);
  // The wheel sits at (0.12, 0.175, 0) in base_link whatever the spawn pose.
  EXPECT_EQ(truth.frame_id, "base_link");
  EXPECT_NEAR(truth.pose.position.x(), 0.12, 2e-3);
  EXPECT_NEAR(truth.pose.position.y(), 0.175, 2e-3);
  EXPECT_NEAR(truth.pose.position.z(), 0.0, 2e-3);
}

TEST(GroundTruth, NoiseOnTheTwistIsSeededWithTheGivenDeviation) {
  auto samples = [] {
    Simulation sim(flatWorldWithGravity(0), SimConfig());
    spawnMovingBox(&sim, p3d("<bodyName>body</bodyName><topicName>truth</topicName>"
                             "<gaussianNoise>0.1</gaussianNoise>"));
    std::vector<double> vx;
    for (int i = 0; i < 2000; ++i) vx.push_back(sim.readGroundTruth("box", 0).twist_in_child.linear.x());
    const OdometryData last = sim.readGroundTruth("box", 0);
    EXPECT_NEAR(last.pose.position.x(), 0.0, 1e-9);  // the pose has no noise
    EXPECT_DOUBLE_EQ(last.pose_covariance[0], 0.01);
    EXPECT_DOUBLE_EQ(last.twist_covariance[35], 0.01);
    return vx;
  };
  const std::vector<double> first = samples();
  EXPECT_EQ(first, samples());  // the same seed, the same draws
  double mean = 0, square = 0;
  for (double v : first) mean += v / first.size();
  for (double v : first) square += (v - mean) * (v - mean) / (first.size() - 1);
  // 2000 draws: the mean within 3 sd / sqrt(2000) = 0.0067, the sd within 5 %.
  EXPECT_NEAR(mean, 0.5, 0.0067);
  EXPECT_NEAR(std::sqrt(square), 0.1, 0.005);
}

TEST(GroundTruth, IsDueAtItsUpdateRate) {
  Simulation sim(flatWorldWithGravity(0), SimConfig());
  spawnMovingBox(&sim, p3d("<bodyName>body</bodyName><topicName>truth</topicName>"
                           "<updateRate>50</updateRate>"));
  int due = 0;
  for (int k = 0; k < 1000; ++k) {
    for (const DueSensor& d : sim.step()) due += d.kind == SensorKind::GroundTruth;
  }
  EXPECT_EQ(due, 50);
}

TEST(GroundTruth, MissingBodyOrTopicAndUnknownLinksAreLoadErrors) {
  try {
    parseRobot(boxUrdf(1, p3d("<bodyName>body</bodyName>")), "box");
    FAIL() << "loaded without <topicName>";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("<topicName> is missing"), std::string::npos)
        << e.what();
  }
  Simulation sim(flatWorld(), SimConfig());
  const RobotSpec spec = parseRobot(
      boxUrdf(1, p3d("<bodyName>chassis</bodyName><topicName>t</topicName>")), "box");
  try {
    sim.spawnRobot("box", spec, Pose3());
    FAIL() << "spawned with a missing body";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()),
              "robot 'box': libgazebo_ros_p3d.so <bodyName> names link 'chassis' that does "
              "not exist");
  }
}
