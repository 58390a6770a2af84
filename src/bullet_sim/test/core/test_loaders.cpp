// Loader tests: the Burger's URDF and Gazebo tags, the round-track world, and
// one fixture per bad input with the error text asserted.
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "load_errors.h"

using namespace bullet_sim;

using bullet_sim_test::fixture;
using bullet_sim_test::loadErrorOf;

namespace {

bool hasWarningWith(const RobotSpec& spec, const std::string& text) {
  for (const std::string& w : spec.warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

const char* kMinimalRobot = R"(<robot name="m">
  <link name="base_link">
    <collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision>
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <link name="bumper"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>
  <joint name="bumper_joint" type="fixed"><parent link="base_link"/><child link="bumper"/></joint>
  <gazebo reference="base_link">
    <sensor type="sonar" name="front_sonar"/>
  </gazebo>
  <gazebo>
    <plugin name="gripper" filename="libgazebo_ros_vacuum_gripper.so"/>
  </gazebo>
</robot>)";

}  // namespace

TEST(RobotLoader, BurgerSensorsAndDriveFromGazeboTags) {
  const RobotSpec spec = bullet_sim_test::burgerSpec();
  EXPECT_EQ(spec.name, "turtlebot3_burger");
  ASSERT_EQ(spec.rays.size(), 1u);
  const RaySpec& ray = spec.rays[0];
  EXPECT_EQ(ray.link, "base_scan");
  EXPECT_EQ(ray.topic, "scan");
  EXPECT_EQ(ray.frame_id, "base_scan");
  EXPECT_EQ(ray.samples, 360);
  EXPECT_DOUBLE_EQ(ray.update_rate_hz, 5);
  EXPECT_DOUBLE_EQ(ray.range_min_m, 0.12);
  EXPECT_DOUBLE_EQ(ray.range_max_m, 3.5);
  EXPECT_DOUBLE_EQ(ray.range_resolution_m, 0.015);
  EXPECT_DOUBLE_EQ(ray.noise_stddev_m, 0.01);
  EXPECT_DOUBLE_EQ(ray.max_angle_rad, 6.28319);

  ASSERT_EQ(spec.imus.size(), 1u);
  EXPECT_EQ(spec.imus[0].link, "imu_link");
  EXPECT_EQ(spec.imus[0].topic, "imu");
  EXPECT_DOUBLE_EQ(spec.imus[0].update_rate_hz, 200);

  ASSERT_TRUE(spec.diff_drive.has_value());
  const DiffDriveSpec& d = *spec.diff_drive;
  EXPECT_EQ(d.left_joint, "wheel_left_joint");
  EXPECT_EQ(d.right_joint, "wheel_right_joint");
  EXPECT_DOUBLE_EQ(d.wheel_separation_m, 0.160);
  EXPECT_DOUBLE_EQ(d.wheel_diameter_m, 0.066);
  EXPECT_DOUBLE_EQ(d.wheel_torque_nm, 10);
  EXPECT_DOUBLE_EQ(d.wheel_acceleration, 1);
  EXPECT_DOUBLE_EQ(d.update_rate_hz, 30);
  EXPECT_EQ(d.odometry_source, OdomSource::World);
  EXPECT_TRUE(d.publish_wheel_joint_state);

  ASSERT_EQ(spec.cameras.size(), 1u);
  EXPECT_EQ(spec.cameras[0].width, 640);
  EXPECT_DOUBLE_EQ(spec.cameras[0].horizontal_fov_rad, 1.5707);

  ASSERT_TRUE(spec.surfaces.count("wheel_left_link"));
  EXPECT_DOUBLE_EQ(spec.surfaces.at("wheel_left_link").mu1, 0.1);
  EXPECT_DOUBLE_EQ(spec.surfaces.at("caster_back_link").kp, 1000000.0);
  EXPECT_FALSE(spec.visuals.empty());
  // Its plugin-less <sensor type="imu"> is published by the model's IMU plugin.
  EXPECT_TRUE(spec.warnings.empty()) << ::testing::PrintToString(spec.warnings);
}

TEST(RobotLoader, UnsupportedPluginSensorAndMasslessCollisionAreNamedInWarnings) {
  const RobotSpec spec = parseRobot(kMinimalRobot, "robot_description");
  EXPECT_TRUE(hasWarningWith(spec, "libgazebo_ros_vacuum_gripper.so")) << ::testing::PrintToString(spec.warnings);
  EXPECT_TRUE(hasWarningWith(spec, "sonar"));
  EXPECT_TRUE(hasWarningWith(spec, "link 'bumper' has <collision> but no <inertial>"));
}

TEST(RobotLoader, UrdfWithoutBaseLinkNamesTheLoopThatLeavesNoRoot) {
  const std::string path = fixture("urdf_no_root.urdf");
  EXPECT_EQ(loadErrorOf([&] { parseRobotFile(path); }),
            path + ": joints 'a_to_b' (a -> b), 'b_to_a' (b -> a) form a loop: a URDF is a tree");
}

TEST(RobotLoader, UrdfWithTwoRootsIsRejected) {
  const std::string error =
      loadErrorOf([] { parseRobotFile(fixture("urdf_two_roots.urdf")); });
  EXPECT_NE(error.find("Two root links found: [base_link] and [stray_link]"), std::string::npos)
      << error;
}

TEST(RobotLoader, MalformedGazeboValueNamesElementAndValue) {
  std::string urdf = bullet_sim_test::burgerUrdf();
  const std::string from = "<wheelSeparation>0.160</wheelSeparation>";
  urdf.replace(urdf.find(from), from.size(), "<wheelSeparation>wide</wheelSeparation>");
  const std::string error = loadErrorOf([&] { parseRobot(urdf, "robot_description"); });
  EXPECT_NE(error.find("robot_description"), std::string::npos) << error;
  EXPECT_NE(error.find("<wheelSeparation>: 'wide' is not a number"), std::string::npos) << error;
}

TEST(RobotLoader, MisspelledPluginParameterIsNamedWithTheNearestKnownOne) {
  std::string urdf = bullet_sim_test::burgerUrdf();
  const std::string from = "<wheelSeparation>0.160</wheelSeparation>";
  urdf.replace(urdf.find(from), from.size(), "<wheelSeperation>0.160</wheelSeperation>");
  const RobotSpec spec = parseRobot(urdf, "robot_description");
  EXPECT_TRUE(hasWarningWith(spec, "<wheelSeperation>: libgazebo_ros_diff_drive.so has no such "
                               "parameter (did you mean <wheelSeparation>?): ignored"));
  // The Burger as written has no unknown parameter.
  for (const std::string& w : bullet_sim_test::burgerSpec().warnings)
    EXPECT_EQ(w.find("no such parameter"), std::string::npos) << w;
}

TEST(RobotLoader, CameraThatCannotBeRenderedIsALoadError) {
  const std::string fov = "<horizontal_fov>1.5707</horizontal_fov>";
  std::string zero_fov = bullet_sim_test::burgerUrdf();
  ASSERT_NE(zero_fov.find(fov), std::string::npos);
  zero_fov.replace(zero_fov.find(fov), fov.size(), "<horizontal_fov>0</horizontal_fov>");
  EXPECT_NE(loadErrorOf([&] { parseRobot(zero_fov, "robot_description"); })
                .find("<camera> <horizontal_fov>: '0' must be in (0, pi) radians"),
            std::string::npos);
  const std::string format = "<format>R8G8B8</format>";
  std::string bad_format = bullet_sim_test::burgerUrdf();
  ASSERT_NE(bad_format.find(format), std::string::npos);
  bad_format.replace(bad_format.find(format), format.size(), "<format>YUV422</format>");
  EXPECT_NE(loadErrorOf([&] { parseRobot(bad_format, "robot_description"); })
                .find("<image> <format>: 'YUV422' is not R8G8B8, B8G8R8, L8, R16G16B16 or L16"),
            std::string::npos);
}

TEST(RobotLoader, MissingRobotFileIsNamed) {
  const std::string path = fixture("no_such.urdf");
  const std::string error = loadErrorOf([&] { parseRobotFile(path); });
  EXPECT_EQ(error, path + ": cannot read the robot file");
}

TEST(RobotLoader, DiffDriveNamingMissingJointFailsAtSpawn) {
  const RobotSpec spec = parseRobotFile(fixture("urdf_diff_drive_missing_joint.urdf"));
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  const std::string error = loadErrorOf([&] { sim.spawnRobot("r1", spec, Pose3()); });
  EXPECT_NE(error.find("<leftJoint> names joint 'wheel_left_joint' that does not exist"),
            std::string::npos)
      << error;
  EXPECT_TRUE(sim.robotNames().empty());
}

TEST(RobotLoader, SpawnNameClashIsRejected) {
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  const RobotSpec spec = bullet_sim_test::burgerSpec();
  sim.spawnRobot("burger", spec, Pose3());
  const std::string error = loadErrorOf([&] { sim.spawnRobot("burger", spec, Pose3()); });
  EXPECT_NE(error.find("a robot named 'burger' already exists"), std::string::npos) << error;
}

TEST(WorldLoader, RoundTrackHasWallsGroundAndStartLine) {
  const WorldSpec world = loadWorldFile(bullet_sim_test::roundTrackPath());
  int walls = 0, planes = 0, visual_only = 0;
  for (const StaticShape& s : world.shapes) {
    if (s.kind == StaticShape::Box && s.collides) {
      ++walls;
      EXPECT_DOUBLE_EQ(s.size.x(), 0.015);
      EXPECT_DOUBLE_EQ(s.size.z(), 0.5);
      EXPECT_NEAR(s.rgba[0], 0.57, 1e-6);
      EXPECT_NEAR(s.rgba[1], 0.417, 1e-6);
      EXPECT_NEAR(s.rgba[2], 0.25, 1e-6);
    }
    if (s.kind == StaticShape::Plane) ++planes;
    if (!s.collides) ++visual_only;
  }
  EXPECT_EQ(walls, 21);
  EXPECT_EQ(planes, 1);
  EXPECT_EQ(visual_only, 1);  // the start line
  EXPECT_NEAR(world.gravity.z(), -9.8, 1e-9);
  EXPECT_DOUBLE_EQ(world.max_step_size_s, 0.001);
}

TEST(WorldLoader, MissingFileNamesThePath) {
  const std::string path = fixture("no_such.world");
  const std::string error = loadErrorOf([&] { loadWorldFile(path); });
  EXPECT_NE(error.find(path + ": world file does not exist"), std::string::npos) << error;
}

TEST(WorldLoader, MalformedXmlNamesPathAndParserMessage) {
  const std::string path = fixture("world_malformed.world");
  const std::string error = loadErrorOf([&] { loadWorldFile(path); });
  EXPECT_NE(error.find(path + ": invalid SDF world: malformed XML"), std::string::npos) << error;
  EXPECT_NE(error.find("XML_ERROR_MISMATCHED_ELEMENT"), std::string::npos) << error;
  EXPECT_NE(error.find("Line number=5"), std::string::npos) << error;
}

TEST(WorldLoader, SdfVersionThatIsNotANumberNamesPathAndValue) {
  const std::string path = fixture("world_bad_sdf_version.world");
  EXPECT_EQ(loadErrorOf([&] { loadWorldFile(path); }),
            path + ": invalid SDF world: <sdf version=\"1.;\">: not a version number such as "
                   "\"1.6\"");
}

TEST(WorldLoader, UnsupportedGeometryNamesFileModelLinkAndType) {
  const std::string path = fixture("world_heightmap.world");
  EXPECT_EQ(loadErrorOf([&] { loadWorldFile(path); }),
            path + ": model 'statue' link 'body' collision: geometry type 'heightmap' is not "
                   "supported (box, cylinder, sphere, plane, mesh are)");
}
