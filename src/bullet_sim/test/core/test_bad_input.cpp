// Bad robot descriptions and worlds, one fixture per failure mode: each is a LoadError (or a
// warning) whose message names the file, the element and the offending value, loaded through
// the entry points the node uses (parseRobot via parseRobotFile, loadWorldFile).
#include <limits>
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

/// The load error of fixture `name` as a robot, and its path for the assertions.
struct RobotError {
  explicit RobotError(const std::string& name)
      : path(fixture(name)), text(loadErrorOf([&] { parseRobotFile(path); })) {}
  bool has(const std::string& fragment) const { return text.find(fragment) != std::string::npos; }
  std::string path, text;
};

std::string worldErrorOf(const std::string& name) {
  return loadErrorOf([&] { loadWorldFile(fixture(name)); });
}

}  // namespace

// ------------------------------------------------------------ URDF structure ----

TEST(BadUrdf, TextThatIsNotXmlNamesFileAndParserPosition) {
  const RobotError e("urdf_not_xml.urdf");
  EXPECT_TRUE(e.has(e.path + ": invalid URDF: not well-formed XML: "
                             "Error=XML_ERROR_PARSING_TEXT ErrorID=8 (0x8) Line number=1"))
      << e.text;
}

TEST(BadUrdf, NoRobotElement) {
  const RobotError e("urdf_no_robot.urdf");
  EXPECT_EQ(e.text, e.path + ": invalid URDF: Could not find the 'robot' element in the xml file");
}

TEST(BadUrdf, JointLoopBesideTheTreeNamesItsJoints) {
  // urdfdom takes base_link as the root and drops the loop: it was a silent half-load.
  const RobotError e("urdf_joint_loop.urdf");
  EXPECT_EQ(e.text, e.path + ": joints 'a_to_b' (arm_a -> arm_b), 'b_to_a' (arm_b -> arm_a) "
                             "form a loop: a URDF is a tree");
}

TEST(BadUrdf, LinkWithTwoParentJointsNamesBoth) {
  // urdfdom keeps one parent and hands back a cycle, which used to overflow the stack.
  const RobotError e("urdf_two_parents.urdf");
  EXPECT_EQ(e.text, e.path + ": link 'arm_a' is the child of joints 'base_a' and 'b_to_a': a "
                             "URDF is a tree (one parent joint per link)");
}

TEST(BadUrdf, MissingParentLinkNamesJointAndLink) {
  const RobotError e("urdf_missing_parent.urdf");
  EXPECT_TRUE(e.has(e.path + ": invalid URDF: Failed to build tree: parent link [chassis] of "
                             "joint [lid_joint] not found"))
      << e.text;
}

TEST(BadUrdf, MissingChildLinkNamesJointAndLink) {
  const RobotError e("urdf_missing_child.urdf");
  EXPECT_EQ(e.text, e.path + ": invalid URDF: Failed to build tree: child link [lid] of joint "
                             "[lid_joint] not found");
}

TEST(BadUrdf, UnknownJointTypeNamesJointAndType) {
  const RobotError e("urdf_unknown_joint_type.urdf");
  EXPECT_TRUE(e.has(e.path + ": invalid URDF: Joint [door_joint] has no known type [hinge]"))
      << e.text;
}

TEST(BadUrdf, NanInAnOriginNamesJointAndValue) {
  const RobotError e("urdf_nan_origin.urdf");
  EXPECT_TRUE(e.has(e.path + ": invalid URDF: Unable to parse component [nan]")) << e.text;
  EXPECT_TRUE(e.has("Malformed parent origin element for joint [arm_joint]")) << e.text;
}

TEST(BadUrdf, InfInAnAxisNamesJointAndValue) {
  const RobotError e("urdf_inf_axis.urdf");
  EXPECT_TRUE(e.has(e.path + ": invalid URDF: Malformed axis element for joint [arm_joint]: "
                             "Unable to parse component [inf]"))
      << e.text;
}

TEST(BadUrdf, NanInACollisionOriginIsNotLeftOut) {
  // urdfdom logs the error, drops the collision and returns the model: a half-load.
  const RobotError e("urdf_nan_collision_origin.urdf");
  EXPECT_EQ(e.text, e.path + ": invalid URDF: Unable to parse component [nan] to a double "
                             "(while parsing a vector value); Could not parse collision element "
                             "for Link [base_link]");
}

TEST(BadUrdf, NegativeBoxSizeNamesLinkAndValue) {
  const RobotError e("urdf_negative_box_size.urdf");
  EXPECT_EQ(e.text, e.path + ": link 'base_link' <collision>: <box size>: '0.2 -0.2 0.1' must "
                             "be finite and not negative");
}

// ------------------------------------------------------------ mass and inertia ----

TEST(BadUrdf, NanInAnInertiaIsNotZeroed) {
  // urdfdom logs the error and hands back the link with every moment 0.
  const RobotError e("urdf_nan_inertia.urdf");
  EXPECT_EQ(e.text, e.path + ": invalid URDF: Inertial: inertia element ixx is not a valid "
                             "double; Could not parse inertial element for Link [base_link]");
}

TEST(BadUrdf, ZeroMassNamesLinkAndValue) {
  const RobotError e("urdf_zero_mass.urdf");
  EXPECT_EQ(e.text, e.path + ": link 'base_link' <inertial> <mass>: '0' must be > 0");
}

TEST(BadUrdf, NegativeMassNamesLinkAndValue) {
  const RobotError e("urdf_negative_mass.urdf");
  EXPECT_EQ(e.text, e.path + ": link 'base_link' <inertial> <mass>: '-2.5' must be > 0");
}

TEST(BadUrdf, NegativeMomentNamesLinkTensorAndPrincipalMoments) {
  const RobotError e("urdf_inertia_negative_moment.urdf");
  EXPECT_EQ(e.text, e.path + ": link 'base_link' <inertial> <inertia>: ixx 0.01 ixy 0 ixz 0 "
                             "iyy -0.01 iyz 0 izz 0.01 has principal moments -0.01 0.01 0.01: "
                             "they must all be > 0 (the tensor must be positive definite)");
}

TEST(BadUrdf, ProductOfInertiaThatMakesTheTensorIndefinite) {
  // [[a, b], [b, a]] has eigenvalues a - b and a + b: 0.01 -+ 0.02, and izz 0.01.
  const RobotError e("urdf_inertia_off_diagonal.urdf");
  EXPECT_TRUE(e.has(e.path + ": link 'base_link' <inertial> <inertia>: ixx 0.01 ixy 0.02 ixz 0 "
                             "iyy 0.01 iyz 0 izz 0.01 has principal moments -0.01 0.01 0.03: "
                             "they must all be > 0"))
      << e.text;
}

TEST(BadUrdf, MomentsBreakingTheTriangleInequality) {
  // 0.01 + 0.01 < 0.05: all positive, and still no body has them.
  const RobotError e("urdf_inertia_triangle.urdf");
  EXPECT_EQ(e.text, e.path + ": link 'base_link' <inertial> <inertia>: ixx 0.01 ixy 0 ixz 0 "
                             "iyy 0.01 iyz 0 izz 0.05 has principal moments 0.01 0.01 0.05: the "
                             "largest exceeds the sum of the other two, which no rigid body "
                             "allows");
}

TEST(BadUrdf, ThinDiscOnTheEdgeOfTheTriangleInequalityLoads) {
  // A thin disc of mass 1, radius 0.1: ixx = iyy = m r^2 / 4 = 0.0025, izz = m r^2 / 2 = 0.005.
  const std::string urdf = R"(<robot name="disc"><link name="base_link"><inertial>
      <mass value="1"/><inertia ixx="0.0025" ixy="0" ixz="0" iyy="0.0025" iyz="0" izz="0.005"/>
      </inertial></link></robot>)";
  EXPECT_EQ(loadErrorOf([&] { parseRobot(urdf, "robot_description"); }), "");
}

TEST(BadUrdf, CollisionWithoutInertialIsAWarningAndTheRobotRuns) {
  const RobotSpec spec = parseRobotFile(fixture("urdf_collision_without_inertial.urdf"));
  ASSERT_EQ(spec.warnings.size(), 1u) << ::testing::PrintToString(spec.warnings);
  EXPECT_EQ(spec.warnings[0], "link 'bumper' has <collision> but no <inertial>: it is given no "
                              "mass (Gazebo would drop it)");
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("bumpy", spec, Pose3());
  for (int i = 0; i < 100; ++i) sim.step();
  EXPECT_TRUE(sim.modelPose("bumpy").position.allFinite());
}

// ------------------------------------------------------------ sensors ----

TEST(BadUrdf, LidarWithZeroSamples) {
  const RobotError e("urdf_ray_zero_samples.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"base_link\"> <sensor name=\"front_lidar\"> "
                             "<horizontal> <samples>: '0' is not a count >= 1");
}

TEST(BadUrdf, LidarWithMinAngleAboveMaxAngle) {
  const RobotError e("urdf_ray_min_angle_above_max.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"base_link\"> <sensor name=\"front_lidar\"> "
                             "<horizontal>: min_angle 1.5 must not be above max_angle -1.5");
}

TEST(BadUrdf, LidarWithRangeMinAboveMax) {
  const RobotError e("urdf_ray_range_min_above_max.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"base_link\"> <sensor name=\"front_lidar\"> "
                             "<range>: min 12 must be >= 0 and below max 3.5");
}

TEST(BadUrdf, SensorWithNegativeUpdateRate) {
  const RobotError e("urdf_sensor_negative_rate.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"base_link\"> <sensor name=\"front_lidar\"> "
                             "<update_rate>: '-5' is not a rate >= 0 Hz");
}

TEST(BadUrdf, NanFrictionNamesLinkAndValue) {
  const RobotError e("urdf_nan_friction.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"wheel\"> <mu1>: 'nan' is not a friction "
                             "coefficient");
}

TEST(BadUrdf, CameraWithZeroFieldOfView) {
  const RobotError e("urdf_camera_zero_fov.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"base_link\"> <sensor name=\"front_camera\"> "
                             "<camera> <horizontal_fov>: '0' must be in (0, pi) radians");
}

TEST(BadUrdf, CameraWithUnknownImageFormat) {
  const RobotError e("urdf_camera_unknown_format.urdf");
  EXPECT_EQ(e.text, e.path + ": <gazebo reference=\"base_link\"> <sensor name=\"front_camera\"> "
                             "<camera> <image> <format>: 'YUV422' is not R8G8B8, B8G8R8, L8, "
                             "R16G16B16 or L16 (or RGB_INT8, BGR_INT8, L_INT8, RGB_INT16, "
                             "L_INT16)");
}

// ------------------------------------------------------------ files it names ----

TEST(BadUrdf, MissingCollisionMeshNamesLinkAndUri) {
  const RobotError e("urdf_missing_mesh.urdf");
  EXPECT_TRUE(e.has(e.path + ": link 'base_link' collision mesh 'meshes/no_such_chassis.stl': "
                             "file not found"))
      << e.text;
}

// ------------------------------------------------------------ worlds ----

TEST(BadWorld, NegativeBoxSizeNamesModelLinkCollisionAndValue) {
  EXPECT_EQ(worldErrorOf("world_negative_box_size.world"),
            fixture("world_negative_box_size.world") +
                ": model 'crate' link 'body' collision 'collision': <box> <size>: '1 -0.5 0.3' "
                "must be finite and not negative");
}

TEST(BadWorld, NegativeCylinderRadius) {
  EXPECT_EQ(worldErrorOf("world_negative_radius.world"),
            fixture("world_negative_radius.world") +
                ": model 'crate' link 'body' collision 'collision': <cylinder> <radius>: '-0.2' "
                "must be finite and not negative");
}

TEST(BadWorld, NegativeCylinderLength) {
  EXPECT_EQ(worldErrorOf("world_negative_length.world"),
            fixture("world_negative_length.world") +
                ": model 'crate' link 'body' collision 'collision': <cylinder> <length>: '-0.5' "
                "must be finite and not negative");
}

TEST(BadWorld, NanFrictionNamesModelLinkCollisionAndValue) {
  EXPECT_EQ(worldErrorOf("world_nan_friction.world"),
            fixture("world_nan_friction.world") +
                ": model 'floor' link 'link' collision 'collision': "
                "<surface><friction><ode><mu>: 'nan' is not a friction coefficient");
}

// Gazebo's FrictionPyramid::SetMu keeps a negative coefficient as FLT_MAX (gazebo_ros_pkgs'
// bumper_test.world has <mu>-1</mu>): it loads, as friction without a limit.
TEST(BadWorld, NegativeFrictionIsUnlimitedAsInGazebo) {
  const WorldSpec w = loadWorldString(R"(<sdf version="1.6"><world name="w"><model name="floor">
        <static>true</static><link name="link"><collision name="collision"><geometry><box>
        <size>1 1 1</size></box></geometry><surface><friction><ode><mu>-0.2</mu><mu2>-1</mu2>
        </ode></friction></surface></collision></link></model></world></sdf>)",
                                      "w.world");
  ASSERT_EQ(w.shapes.size(), 1u);
  EXPECT_EQ(w.shapes[0].friction, static_cast<double>(std::numeric_limits<float>::max()));
  const RobotSpec urdf = parseRobot(R"(<robot name="r"><link name="a"><inertial><mass value="1"/>
      <inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
      <gazebo reference="a"><mu1>-1</mu1><mu2>0.5</mu2></gazebo></robot>)", "r.urdf");
  EXPECT_EQ(urdf.surfaces.at("a").mu1, static_cast<double>(std::numeric_limits<float>::max()));
  EXPECT_EQ(urdf.surfaces.at("a").mu2, 0.5);
}

TEST(BadWorld, NanFrictionOfASpawnedSdfModel) {
  const std::string sdf = R"(<?xml version="1.0"?><sdf version="1.6"><model name="puck">
      <link name="body"><collision name="base"><geometry><sphere><radius>0.1</radius></sphere>
      </geometry><surface><friction><ode><mu>0.5</mu><mu2>nan</mu2></ode></friction></surface>
      </collision></link></model></sdf>)";
  const std::string error = loadErrorOf([&] { parseSdfModelString(sdf, "puck"); });
  EXPECT_NE(error.find("link 'body' collision 'base': <surface><friction><ode><mu2>: 'nan' is "
                       "not a friction coefficient"),
            std::string::npos)
      << error;
}

TEST(BadWorld, NegativeSphereRadiusOfASpawnedSdfModel) {
  const std::string sdf = R"(<?xml version="1.0"?><sdf version="1.6"><model name="ball">
      <link name="body"><collision name="shell"><geometry><sphere><radius>-0.1</radius></sphere>
      </geometry></collision></link></model></sdf>)";
  const std::string error = loadErrorOf([&] { parseSdfModelString(sdf, "ball"); });
  EXPECT_NE(error.find("link 'body' collision 'shell': <sphere> <radius>: '-0.1' must be finite "
                       "and not negative"),
            std::string::npos)
      << error;
}

TEST(BadWorld, SpawnedSdfModelWithImpossibleInertiaNamesModelLinkAndMoments) {
  // The same check as a URDF link's: 0.1 + 0.1 < 0.3.
  const std::string sdf = R"(<?xml version="1.0"?><sdf version="1.6"><model name="cart">
      <link name="body"><inertial><mass>1</mass><inertia><ixx>0.1</ixx><ixy>0</ixy><ixz>0</ixz>
      <iyy>0.1</iyy><iyz>0</iyz><izz>0.3</izz></inertia></inertial></link></model></sdf>)";
  EXPECT_EQ(loadErrorOf([&] { parseSdfModelString(sdf, "cart.sdf"); }),
            "cart.sdf: model 'cart' link 'body' <inertial> <inertia>: ixx 0.1 ixy 0 ixz 0 iyy 0.1 "
            "iyz 0 izz 0.3 has principal moments 0.1 0.1 0.3: the largest exceeds the sum of the "
            "other two, which no rigid body allows");
}
