// Range sensors (libgazebo_ros_range.so), block lasers (libgazebo_ros_block_laser.so) and
// bumpers (libgazebo_ros_bumper.so) of a URDF robot, against geometry worked out by hand: a
// 0.2 m cube of 2 kg resting on the ground, its sensors on the middle of its front face
// (x 0.1, z 0.1 in the world), a static wall whose face is the plane x = 1.0 and, in one
// world, a thin post off to the left.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/simulation.h"
#include "load_errors.h"

using namespace bullet_sim;

namespace {

constexpr double kWallDistance = 0.9;  // sensor (x 0.1) to the wall's face (x 1.0)

/// A ground plane, the wall (0.2 x 4 x 2 centred at x 1.1) and, with `post`, a 0.06 m square
/// post whose centre is 0.55 m from the sensor at yaw 0.2 rad.
WorldSpec world(bool post) {
  const double px = 0.1 + 0.55 * std::cos(0.2), py = 0.55 * std::sin(0.2);
  const std::string post_model =
      "<model name='post'><static>true</static><pose>" + std::to_string(px) + " " +
      std::to_string(py) + " 0.2 0 0 0</pose><link name='link'><collision name='collision'>"
      "<geometry><box><size>0.06 0.06 0.4</size></box></geometry></collision></link></model>";
  return loadWorldString(
      "<sdf version='1.6'><world name='w'>"
      "<model name='ground'><static>true</static><link name='link'><collision name='collision'>"
      "<geometry><plane><normal>0 0 1</normal><size>10 10</size></plane></geometry>"
      "</collision></link></model>"
      "<model name='wall'><static>true</static><pose>1.1 0 1 0 0 0</pose><link name='link'>"
      "<collision name='collision'><geometry><box><size>0.2 4 2</size></box></geometry>"
      "</collision></link></model>" +
          (post ? post_model : std::string()) + "</world></sdf>",
      "w.world");
}

std::string rayElement(const std::string& horizontal, const std::string& vertical,
                       const std::string& range) {
  return "<ray><scan><horizontal>" + horizontal + "</horizontal>" +
         (vertical.empty() ? "" : "<vertical>" + vertical + "</vertical>") + "</scan><range>" +
         range + "</range></ray>";
}

/// The cube with `sensors` in its <gazebo reference="base_link"> block.
RobotSpec cube(const std::string& sensors) {
  return parseRobot(
      "<robot name='cube'><link name='base_link'><inertial><mass value='2'/>"
      "<inertia ixx='0.0133' iyy='0.0133' izz='0.0133' ixy='0' ixz='0' iyz='0'/></inertial>"
      "<collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link>"
      "<gazebo reference='base_link'>" + sensors + "</gazebo></robot>",
      "cube.urdf");
}

const std::string kRangeSensor =
    "<sensor type='ray' name='sonar'><pose>0.1 0 0 0 0 0</pose><update_rate>10</update_rate>" +
    rayElement("<samples>5</samples><min_angle>-0.2</min_angle><max_angle>0.2</max_angle>",
               "<samples>3</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle>",
               "<min>0.02</min><max>2</max>") +
    "<plugin name='r' filename='libgazebo_ros_range.so'><topicName>sonar</topicName>"
    "<frameName>sonar_link</frameName><fov>0.4</fov><radiation>infrared</radiation>"
    "</plugin></sensor>";

/// The cube spawned resting on the ground, stepped `steps` ms.
struct CubeOnGround {
  CubeOnGround(bool post, const std::string& sensors, int steps = 10)
      : sim(world(post), SimConfig()) {
    Pose3 pose;
    pose.position.z() = 0.1;
    sim.spawnRobot("cube", cube(sensors), pose);
    for (int i = 0; i < steps; ++i) sim.step();
  }
  Simulation sim;
};

}  // namespace

TEST(RangeSensor, ReadsTheWallStraightAhead) {
  CubeOnGround c(false, kRangeSensor);
  const RangeData r = c.sim.readRange("cube", 0);
  EXPECT_NEAR(r.range, kWallDistance, 1e-4);
  EXPECT_EQ(r.frame_id, "sonar_link");
  EXPECT_TRUE(r.infrared);
  EXPECT_FLOAT_EQ(r.field_of_view, 0.4f);
  EXPECT_FLOAT_EQ(r.min_range, 0.02f);
  EXPECT_FLOAT_EQ(r.max_range, 2.0f);
}

// The post is hit only by the ray at yaw 0.2, pitch 0, entering its near face (x 0.03
// before its centre): (0.55 cos 0.2 - 0.03) / cos 0.2 = 0.55 - 0.03 / cos 0.2.
TEST(RangeSensor, IsTheNearestOfAllItsRays) {
  CubeOnGround c(true, kRangeSensor);
  EXPECT_NEAR(c.sim.readRange("cube", 0).range, 0.55 - 0.03 / std::cos(0.2), 1e-4);
}

TEST(RangeSensor, ReadsItsMaxRangeWhenNoRayHitsAndAddsNoNoiseThen) {
  // Looking back (yaw pi), level: nothing within 2 m.
  CubeOnGround c(false,
                 "<sensor type='ray' name='back'><pose>-0.1 0 0 0 0 3.14159265</pose>" +
                     rayElement("<samples>3</samples><min_angle>-0.1</min_angle>"
                                "<max_angle>0.1</max_angle>",
                                "", "<min>0.02</min><max>2</max>") +
                     "<plugin name='r' filename='libgazebo_ros_range.so'>"
                     "<gaussianNoise>0.1</gaussianNoise></plugin></sensor>");
  const RangeData r = c.sim.readRange("cube", 0);
  EXPECT_EQ(r.range, 2.0f);
  EXPECT_EQ(r.frame_id, "/world");  // the plugin's default
  EXPECT_FALSE(r.infrared);
  EXPECT_FLOAT_EQ(r.field_of_view, 0.05f);
}

TEST(RangeSensor, NoiseIsGaussianWithTheGivenDeviationAndSeeded) {
  const std::string noisy =
      "<sensor type='ray' name='sonar'><pose>0.1 0 0 0 0 0</pose>" +
      rayElement("<samples>1</samples>", "", "<min>0.02</min><max>2</max>") +
      "<plugin name='r' filename='libgazebo_ros_range.so'><gaussianNoise>0.01</gaussianNoise>"
      "</plugin></sensor>";
  CubeOnGround a(false, noisy), b(false, noisy);
  double sum = 0, sum_sq = 0;
  constexpr int kReads = 2000;
  for (int i = 0; i < kReads; ++i) {
    const double r = a.sim.readRange("cube", 0).range;
    EXPECT_EQ(r, b.sim.readRange("cube", 0).range);  // same seed, same readings
    sum += r - kWallDistance;
    sum_sq += (r - kWallDistance) * (r - kWallDistance);
  }
  EXPECT_NEAR(sum / kReads, 0.0, 0.001);
  EXPECT_NEAR(std::sqrt(sum_sq / kReads), 0.01, 0.001);
}

// Three by two rays at yaw -0.2, 0, 0.2 and pitch -0.1, 0.1 meet the wall plane x = 0.9 (in
// the sensor frame) at range 0.9 / (cos pitch cos yaw). Gazebo's plugin gives reading (i, j)
// the range of ray (i, j) and places it half way between rays i and i + 1 (the last: its own
// ray), between pitches j and j + 1: at yaw -0.1, 0.1, 0.2 and pitch 0, 0.1; row by row,
// pitch outer.
TEST(BlockLaser, PointsTakeEachRaysRangeAlongGazebosInBetweenDirections) {
  CubeOnGround c(false,
                 "<sensor type='ray' name='block'><pose>0.1 0 0 0 0 0</pose>" +
                     rayElement("<samples>3</samples><min_angle>-0.2</min_angle>"
                                "<max_angle>0.2</max_angle>",
                                "<samples>2</samples><min_angle>-0.1</min_angle>"
                                "<max_angle>0.1</max_angle>",
                                "<min>0.05</min><max>2</max>") +
                     "<plugin name='b' filename='libgazebo_ros_block_laser.so'>"
                     "<topicName>cloud</topicName><frameName>block_frame</frameName>"
                     "</plugin></sensor>");
  const BlockLaserCloudData cloud = c.sim.readBlockLaser("cube", 0);
  EXPECT_EQ(cloud.frame_id, "block_frame");
  ASSERT_EQ(cloud.points.size(), 6u);
  ASSERT_EQ(cloud.intensities.size(), 6u);
  const double ray_yaws[] = {-0.2, 0.0, 0.2}, ray_pitches[] = {-0.1, 0.1};
  const double yaws[] = {-0.1, 0.1, 0.2}, pitches[] = {0.0, 0.1};
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3f& p = cloud.points[j * 3 + i];
      const double r = kWallDistance / (std::cos(ray_pitches[j]) * std::cos(ray_yaws[i]));
      EXPECT_NEAR(p.x(), r * std::cos(pitches[j]) * std::cos(yaws[i]), 1e-4) << i << " " << j;
      EXPECT_NEAR(p.y(), r * std::cos(pitches[j]) * std::sin(yaws[i]), 1e-4) << i << " " << j;
      EXPECT_NEAR(p.z(), r * std::sin(pitches[j]), 1e-4) << i << " " << j;
      EXPECT_EQ(cloud.intensities[j * 3 + i], 0.0f);
    }
  }
}

// With <resolution> 2 there are 2 x 3 = 6 readings along 3 rays: reading i lies at
// i * 2 / 5 rays from the first; its range is interpolated between the two rays around it
// and it points half way between them (reading 5: ray 2 alone). Max range 0.91: the side rays (0.9 / cos 0.2 =
// 0.918 m) miss and read 0.91 exactly, unclipped, as in Gazebo (a ray never reads beyond
// max), without noise; the centre ray's hit (0.9 m) gets it.
TEST(BlockLaser, InterpolatesBetweenRaysAndLeavesMaxRangeReadingsUnclippedAndNoiseless) {
  CubeOnGround c(false,
                 "<sensor type='ray' name='block'><pose>0.1 0 0 0 0 0</pose>" +
                     rayElement("<samples>3</samples><resolution>2</resolution>"
                                "<min_angle>-0.2</min_angle><max_angle>0.2</max_angle>",
                                "", "<min>0.05</min><max>0.91</max>") +
                     "<plugin name='b' filename='libgazebo_ros_block_laser.so'>"
                     "<gaussianNoise>0.001</gaussianNoise></plugin></sensor>");
  const BlockLaserCloudData cloud = c.sim.readBlockLaser("cube", 0);
  EXPECT_EQ(cloud.frame_id, "/world");
  ASSERT_EQ(cloud.points.size(), 6u);
  // Reading 0: ray 0's range (0.91), between rays 0 and 1 (yaw -0.1); reading 5: ray 2.
  EXPECT_NEAR(cloud.points[0].x(), 0.91 * std::cos(-0.1), 1e-6);
  EXPECT_NEAR(cloud.points[0].y(), 0.91 * std::sin(-0.1), 1e-6);
  EXPECT_NEAR(cloud.points[5].x(), 0.91 * std::cos(0.2), 1e-6);
  EXPECT_NEAR(cloud.points[5].y(), 0.91 * std::sin(0.2), 1e-6);
  EXPECT_NEAR(cloud.points[0].norm(), 0.91, 1e-6);
  // Reading 1: 0.4 of the way from ray 0 (0.91) to ray 1 (0.9): 0.906, at yaw -0.1.
  const double r1 = 0.6 * 0.91 + 0.4 * 0.9;
  EXPECT_NEAR(cloud.points[1].x(), r1 * std::cos(-0.1), 0.005);
  EXPECT_NEAR(cloud.points[1].y(), r1 * std::sin(-0.1), 0.005);
  // Reading 2: 0.8 of the way: 0.902; noise of 1 mm on each axis.
  EXPECT_NEAR(cloud.points[2].norm(), 0.2 * 0.91 + 0.8 * 0.9, 0.005);
  EXPECT_NE(cloud.points[2].norm(), static_cast<float>(0.2 * 0.91 + 0.8 * 0.9));
}

TEST(Bumper, ContactsOfACubeRestingOnTheGroundCarryItsWeight) {
  // 2 s: the cube has settled (and Bullet has put it to sleep, which keeps its contacts).
  for (int steps : {1000, 3000}) {
    CubeOnGround c(false,
                   "<sensor type='contact' name='bumper'><update_rate>20</update_rate><contact>"
                   "<collision>base_link_collision</collision></contact>"
                   "<plugin name='b' filename='libgazebo_ros_bumper.so'>"
                   "<bumperTopicName>bumps</bumperTopicName></plugin></sensor>",
                   steps);
    const ContactsData contacts = c.sim.readBumper("cube", 0);
    EXPECT_EQ(contacts.frame_id, "world");
    ASSERT_EQ(contacts.states.size(), 1u) << steps;
    const ContactStateData& s = contacts.states[0];
    EXPECT_EQ(s.collision1_name, "cube::base_link::base_link_collision");
    EXPECT_EQ(s.collision2_name, "ground::link::collision");
    ASSERT_GE(s.positions.size(), 3u);
    ASSERT_EQ(s.forces.size(), s.positions.size());
    Eigen::Vector3d total(0, 0, 0);
    for (size_t k = 0; k < s.positions.size(); ++k) {
      // On the cube's bottom face (its corners), pushed up by the ground.
      EXPECT_NEAR(s.positions[k].z(), 0.0, 0.005);
      EXPECT_LE(std::fabs(s.positions[k].x()), 0.1 + 1e-3);
      EXPECT_LE(std::fabs(s.positions[k].y()), 0.1 + 1e-3);
      EXPECT_NEAR(s.normals[k].z(), 1.0, 1e-6);
      EXPECT_GE(s.depths[k], 0.0);
      EXPECT_LT(s.depths[k], 0.005);
      total += s.forces[k];
    }
    // m g = 2 kg * 9.8 m/s^2, and nothing sideways; the moments about the centre of
    // mass balance.
    EXPECT_NEAR(total.z(), 19.6, 0.05) << steps;
    EXPECT_NEAR(total.x(), 0.0, 0.01);
    EXPECT_NEAR(total.y(), 0.0, 0.01);
    EXPECT_NEAR((s.total_force - total).norm(), 0.0, 1e-9);
    EXPECT_LT(s.total_torque.norm(), 0.05);
  }
}

TEST(Bumper, NothingTouchesACubeInTheAir) {
  Simulation sim(world(false), SimConfig());
  Pose3 pose;
  pose.position.z() = 2;
  sim.spawnRobot("cube",
                 cube("<sensor type='contact' name='bumper'><contact><collision>"
                      "base_link_collision</collision></contact>"
                      "<plugin name='b' filename='libgazebo_ros_bumper.so'/></sensor>"),
                 pose);
  for (int i = 0; i < 100; ++i) sim.step();
  EXPECT_TRUE(sim.readBumper("cube", 0).states.empty());
}

TEST(Bumper, AnUnknownCollisionIsALoadErrorNamingItAndTheLinksCollisions) {
  Simulation sim(world(false), SimConfig());
  const std::string error = bullet_sim_test::loadErrorOf([&] {
    sim.spawnRobot("cube",
                   cube("<sensor type='contact' name='bumper'><contact><collision>"
                        "base_collision</collision></contact>"
                        "<plugin name='b' filename='libgazebo_ros_bumper.so'/></sensor>"),
                   Pose3());
  });
  EXPECT_EQ(error,
            "robot 'cube': bumper 'bumper' <contact><collision> 'base_collision' is not a "
            "collision of link 'base_link' (it has 'base_link_collision')");
}

TEST(ConeAndContactSensors, AreDueAtTheirSensorsUpdateRates) {
  // Range: <update_rate> 10 and <updateRate> 4: at most one reading per 0.25 s.
  CubeOnGround c(false,
                 kRangeSensor.substr(0, kRangeSensor.find("</plugin>")) +
                     "<updateRate>4</updateRate></plugin></sensor>"
                     "<sensor type='contact' name='bumper'><update_rate>50</update_rate>"
                     "<contact><collision>base_link_collision</collision></contact>"
                     "<plugin name='b' filename='libgazebo_ros_bumper.so'/></sensor>",
                 0);
  int ranges = 0, bumpers = 0;
  for (int i = 0; i < 2000; ++i) {
    for (const DueSensor& due : c.sim.step()) {
      ranges += due.kind == SensorKind::Range;
      bumpers += due.kind == SensorKind::Bumper;
    }
  }
  EXPECT_EQ(ranges, 8);
  EXPECT_EQ(bumpers, 100);
}
