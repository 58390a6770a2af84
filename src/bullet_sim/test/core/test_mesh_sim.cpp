// Meshes in worlds and robots: static triangle meshes the lidar sees where their geometry
// is, a Burger whose base and wheels are STL meshes driving like the primitive one, and
// one generated file per failure mode with the message asserted.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "load_errors.h"
#include "mesh_fixtures.h"

using namespace bullet_sim;
using bullet_sim_test::boxTriangles;
using Eigen::Vector3d;

using bullet_sim_test::loadErrorOf;

namespace {

constexpr double kDt = 0.001;

void run(Simulation* sim, double seconds) {
  for (long i = 0; i < std::lround(seconds / kDt); ++i) sim->step();
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  size_t count = 0;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
    ++count;
  }
  EXPECT_GT(count, 0u) << "'" << from << "' is not in the text";
  return text;
}

/// No resource paths: only file://, absolute and relative names resolve.
UriResolver plainResolver() { return UriResolver(ResourcePaths{}); }

/// The workspace's Burger with its base collision box (0.140 x 0.140 x 0.143) and its wheel
/// cylinders (r 0.033, l 0.018; visual and collision) replaced by STL meshes of the same
/// sizes, written into `dir` (binary STL base, ASCII STL wheel with 48 facets).
RobotSpec meshBurger(const std::string& dir) {
  bullet_sim_test::writeBinaryStl(dir + "/base.stl", boxTriangles(Vector3d(0.140, 0.140, 0.143)));
  bullet_sim_test::writeAsciiStl(dir + "/wheel.stl",
                                 bullet_sim_test::cylinderTriangles(0.033, 0.018, 48));
  std::string urdf = bullet_sim_test::burgerUrdf();
  urdf = replaceAll(urdf, "<box size=\"0.140 0.140 0.143\"/>",
                    "<mesh filename=\"file://" + dir + "/base.stl\"/>");
  urdf = replaceAll(urdf, "<cylinder length=\"0.018\" radius=\"0.033\"/>",
                    "<mesh filename=\"" + dir + "/wheel.stl\" scale=\"1 1 1\"/>");
  return parseRobot(urdf, "mesh burger", plainResolver());
}

/// A ground plane plus `models` (SDF <model> elements), written as world.sdf into `dir`.
std::string writeWorld(const std::string& dir, const std::string& models) {
  const std::string path = dir + "/world.sdf";
  bullet_sim_test::writeText(
      path, "<?xml version='1.0'?><sdf version='1.6'><world name='meshes'>"
            "<model name='ground'><static>true</static><link name='link'><collision name='c'>"
            "<geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>"
            "</collision></link></model>" + models + "</world></sdf>");
  return path;
}

std::string staticMeshModel(const std::string& name, const std::string& pose,
                            const std::string& collision_uri, const std::string& visual_uri) {
  return "<model name='" + name + "'><static>true</static><pose>" + pose +
         "</pose><link name='link'><collision name='c'><geometry><mesh><uri>" + collision_uri +
         "</uri></mesh></geometry></collision><visual name='v'><geometry><mesh><uri>" +
         visual_uri + "</uri></mesh></geometry></visual></link></model>";
}

bool hasWarning(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w == text) return true;
  return false;
}

class MeshWorld : public ::testing::Test {
 protected:
  const std::string dir_ = bullet_sim_test::makeTempDir();
};

}  // namespace

TEST_F(MeshWorld, MeshBurgerLidarSeesAMeshWallAndIntoAConcaveMesh) {
  // Wall: a COLLADA box in centimetres tagged Y_UP but written z up, as Gazebo reads it:
  // 10 cm thick (x), 2 m wide (y), 1 m high; placed at x 1.5 its near face is at x 1.45.
  bullet_sim_test::writeCollada(dir_ + "/wall.dae",
                                boxTriangles(Vector3d(10, 200, 100), Vector3d(0, 0, 50)), 0.01,
                                "Y_UP", Eigen::Vector4f(0.6f, 0.6f, 0.9f, 1));
  // Pocket: a U of three boxes open towards the robot (-y); its back wall's inner face is at
  // y 1.95 + 0 (model at y 0), the mouth at y 1.0. Its convex hull would close the mouth.
  auto pocket = boxTriangles(Vector3d(1.0, 0.1, 1.0), Vector3d(0, 2.0, 0.5));
  for (double x : {-0.55, 0.55}) {
    const auto side = boxTriangles(Vector3d(0.1, 1.1, 1.0), Vector3d(x, 1.5, 0.5));
    pocket.insert(pocket.end(), side.begin(), side.end());
  }
  bullet_sim_test::writeAsciiStl(dir_ + "/pocket.stl", pocket);
  const WorldSpec world = loadWorldFile(
      writeWorld(dir_, staticMeshModel("wall", "1.5 0 0 0 0 0", "wall.dae", "wall.dae") +
                           staticMeshModel("pocket", "0 0 0 0 0 0", "pocket.stl", "pocket.stl")),
      plainResolver());
  EXPECT_TRUE(world.warnings.empty());

  RobotSpec robot = meshBurger(dir_);
  robot.rays[0].noise_stddev_m = 0;
  robot.rays[0].range_resolution_m = 0;
  Simulation sim(world, SimConfig());
  sim.spawnRobot("burger", robot, Pose3());
  run(&sim, 0.5);
  Vector3d lidar;
  for (const LinkPose& link : sim.linkPoses("burger"))
    if (link.link == "base_scan") lidar = link.pose.position;
  const LaserScanData scan = sim.readRay("burger", 0);
  const size_t quarter = std::lround((M_PI / 2) / scan.angle_increment);
  for (size_t i : {size_t(0), size_t(10), size_t(25), scan.ranges.size() - 10}) {
    const double angle = i * scan.angle_increment;
    SCOPED_TRACE("ray " + std::to_string(i));
    EXPECT_NEAR(scan.ranges[i], (1.45 - lidar.x()) / std::cos(angle), 0.002);
  }
  // Straight up the pocket's middle to its back wall.
  const double angle = quarter * scan.angle_increment;
  EXPECT_NEAR(scan.ranges[quarter], (1.95 - lidar.y()) / std::sin(angle), 0.002);
}

TEST_F(MeshWorld, MeshBurgerDrivesLikeThePrimitiveBurger) {
  const RobotSpec mesh_robot = meshBurger(dir_);
  EXPECT_EQ(mesh_robot.collision_meshes.size(), 2u);
  for (const std::string& w : mesh_robot.warnings) EXPECT_EQ(w.find("mesh"), std::string::npos) << w;
  auto drive = [](const RobotSpec& spec) {
    Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
    sim.spawnRobot("burger", spec, Pose3());
    run(&sim, 0.5);
    const Pose3 start = sim.modelPose("burger");
    sim.setCmdVel("burger", 0.2, 0);
    run(&sim, 5.0);
    const Pose3 end = sim.modelPose("burger");
    EXPECT_NEAR(end.position.z(), start.position.z(), 0.003);  // on its wheels
    EXPECT_LT(std::fabs(end.position.y()), 0.03);
    return end.position.x() - start.position.x();
  };
  const double primitive = drive(bullet_sim_test::burgerSpec());
  const double meshes = drive(mesh_robot);
  EXPECT_NEAR(primitive, 1.0, 0.05);
  EXPECT_NEAR(meshes, primitive, 0.03 * primitive);
}

TEST_F(MeshWorld, MissingWorldCollisionMeshIsLeftOutWithAWarningNamingModelLinkUriAndFolder) {
  // As Gazebo, which goes on without a model of its online database that is not installed.
  const std::string path =
      writeWorld(dir_, staticMeshModel("statue", "0 0 0 0 0 0", "missing.stl", "missing.stl"));
  const WorldSpec world = loadWorldFile(path, plainResolver());
  EXPECT_TRUE(hasWarning(world.warnings, path + ": model 'statue' link 'link' collision mesh "
                                                "'missing.stl': file not found (searched " +
                                                dir_ + "): left out (nothing collides with it)"));
  for (const StaticShape& s : world.shapes) EXPECT_FALSE(s.model == "statue" && s.collides);
}

TEST_F(MeshWorld, UnreadableWorldCollisionMeshStopsTheLoad) {
  bullet_sim_test::writeText(dir_ + "/broken.stl", "solid? no: garbage\n");
  const std::string path =
      writeWorld(dir_, staticMeshModel("statue", "0 0 0 0 0 0", "broken.stl", "broken.stl"));
  const std::string error = loadErrorOf([&] { loadWorldFile(path, plainResolver()); });
  EXPECT_EQ(error.rfind(path + ": model 'statue' link 'link' collision mesh 'broken.stl': " +
                            dir_ + "/broken.stl: cannot read mesh",
                        0),
            0u)
      << error;
}

TEST_F(MeshWorld, MissingWorldVisualMeshIsAWarning) {
  bullet_sim_test::writeBinaryStl(dir_ + "/statue.stl", boxTriangles(Vector3d(1, 1, 1)));
  const std::string path =
      writeWorld(dir_, staticMeshModel("statue", "0 0 0 0 0 0", "statue.stl", "missing.dae"));
  const WorldSpec world = loadWorldFile(path, plainResolver());
  EXPECT_TRUE(hasWarning(world.warnings, path + ": model 'statue' link 'link' visual mesh "
                                                "'missing.dae': file not found (searched " +
                                                dir_ + "): not drawn"));
}

TEST_F(MeshWorld, MissingRobotCollisionMeshNamesLinkAndUri) {
  const std::string urdf =
      "<robot name='r'><link name='base_link'><collision><geometry><mesh "
      "filename='package://no_such_package/meshes/base.stl'/></geometry></collision>"
      "<inertial><mass value='1'/><inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/>"
      "</inertial></link></robot>";
  ResourcePaths paths;
  paths.package_paths = {dir_};
  EXPECT_EQ(loadErrorOf([&] { parseRobot(urdf, "robot_description", UriResolver(paths)); }),
            "robot_description: link 'base_link' collision mesh "
            "'package://no_such_package/meshes/base.stl': file not found (searched " +
                dir_ + ")");
}

TEST_F(MeshWorld, CorruptRobotCollisionMeshNamesLinkPathAndReason) {
  bullet_sim_test::writeText(dir_ + "/corrupt.stl", "solid? no: garbage\n");
  const std::string urdf = "<robot name='r'><link name='base_link'><collision><geometry><mesh "
                           "filename='file://" + dir_ + "/corrupt.stl'/></geometry></collision>"
                           "</link></robot>";
  const std::string error =
      loadErrorOf([&] { parseRobot(urdf, "robot_description", plainResolver()); });
  const std::string expected_start = "robot_description: link 'base_link' collision mesh 'file://" +
                                     dir_ + "/corrupt.stl': " + dir_ +
                                     "/corrupt.stl: cannot read mesh: ";
  EXPECT_EQ(error.rfind(expected_start, 0), 0u) << error;
}

TEST_F(MeshWorld, MissingRobotVisualMeshIsAWarningAndTheRobotLoads) {
  const std::string urdf = "<robot name='r'><link name='base_link'><visual><geometry><mesh "
                           "filename='meshes/shell.dae'/></geometry></visual></link></robot>";
  const RobotSpec spec = parseRobot(urdf, "robot_description", plainResolver());
  ASSERT_EQ(spec.visuals.size(), 1u);
  EXPECT_EQ(spec.visuals[0].mesh, nullptr);
  EXPECT_TRUE(hasWarning(spec.warnings, "link 'base_link' visual mesh 'meshes/shell.dae': file "
                                        "not found (searched meshes): not drawn"));
}

TEST_F(MeshWorld, ZeroMeshScaleIsRejected) {
  bullet_sim_test::writeBinaryStl(dir_ + "/box.stl", boxTriangles(Vector3d(1, 1, 1)));
  const std::string urdf = "<robot name='r'><link name='base_link'><collision><geometry><mesh "
                           "filename='" + dir_ + "/box.stl' scale='1 0 1'/></geometry>"
                           "</collision></link></robot>";
  EXPECT_EQ(loadErrorOf([&] { parseRobot(urdf, "robot_description", plainResolver()); }),
            "robot_description: link 'base_link' collision mesh '" + dir_ +
                "/box.stl': scale '1 0 1' must be finite and non-zero");
}

TEST_F(MeshWorld, RobotFileResolvesRelativeMeshesFromItsFolderAndSharesThem) {
  bullet_sim_test::writeBinaryStl(dir_ + "/box.stl", boxTriangles(Vector3d(0.2, 0.2, 0.2)));
  bullet_sim_test::writeText(
      dir_ + "/robot.urdf",
      "<robot name='r'><link name='base_link'><visual><geometry><mesh filename='box.stl'/>"
      "</geometry></visual><collision><geometry><mesh filename='box.stl' scale='2 2 2'/>"
      "</geometry></collision><inertial><mass value='1'/><inertia ixx='0.01' ixy='0' ixz='0' "
      "iyy='0.01' iyz='0' izz='0.01'/></inertial></link></robot>");
  const RobotSpec spec = parseRobotFile(dir_ + "/robot.urdf");
  ASSERT_EQ(spec.visuals.size(), 1u);
  ASSERT_NE(spec.visuals[0].mesh, nullptr);
  EXPECT_EQ(spec.visuals[0].mesh.get(), spec.collision_meshes.at("box.stl").get());
  // Dropped on the ground, the doubled (0.4 m) box comes to rest on its face.
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  Pose3 pose;
  pose.position.z() = 0.5;
  sim.spawnRobot("box", spec, pose);
  run(&sim, 2.0);
  EXPECT_NEAR(sim.modelPose("box").position.z(), 0.2, 0.002);
}

TEST_F(MeshWorld, LidarSeesAMovingBodysConvexHullWhereItIs) {
  // A 0.4 m box robot (one STL mesh, simulated as its hull) resting 1 m ahead of the Burger.
  bullet_sim_test::writeBinaryStl(dir_ + "/crate.stl", boxTriangles(Vector3d(0.4, 0.4, 0.4)));
  const std::string urdf =
      "<robot name='crate'><link name='base_link'><collision><geometry><mesh filename='" + dir_ +
      "/crate.stl'/></geometry></collision><inertial><mass value='1'/><inertia ixx='0.03' "
      "ixy='0' ixz='0' iyy='0.03' iyz='0' izz='0.03'/></inertial></link></robot>";
  RobotSpec burger = bullet_sim_test::burgerSpec();
  burger.rays[0].noise_stddev_m = 0;
  burger.rays[0].range_resolution_m = 0;
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  sim.spawnRobot("burger", burger, Pose3());
  Pose3 crate_pose;
  crate_pose.position = Vector3d(1.0, 0, 0.2);
  sim.spawnRobot("crate", parseRobot(urdf, "crate", plainResolver()), crate_pose);
  run(&sim, 0.5);
  Vector3d lidar;
  for (const LinkPose& link : sim.linkPoses("burger"))
    if (link.link == "base_scan") lidar = link.pose.position;
  const double face_x = sim.modelPose("crate").position.x() - 0.2;
  const LaserScanData scan = sim.readRay("burger", 0);
  for (size_t i : {size_t(0), size_t(5), scan.ranges.size() - 5}) {
    SCOPED_TRACE("ray " + std::to_string(i));
    EXPECT_NEAR(scan.ranges[i], (face_x - lidar.x()) / std::cos(i * scan.angle_increment), 0.002);
  }
  // Beside it (45 degrees) there is nothing.
  EXPECT_TRUE(std::isinf(scan.ranges[std::lround((M_PI / 4) / scan.angle_increment)]));
}

TEST_F(MeshWorld, ZeroWorldMeshScaleNamesModelLinkAndScale) {
  bullet_sim_test::writeBinaryStl(dir_ + "/box.stl", boxTriangles(Vector3d(1, 1, 1)));
  const std::string path = writeWorld(
      dir_, "<model name='flat'><static>true</static><link name='link'><collision name='c'>"
            "<geometry><mesh><uri>box.stl</uri><scale>1 1 0</scale></mesh></geometry>"
            "</collision></link></model>");
  EXPECT_EQ(loadErrorOf([&] { loadWorldFile(path, plainResolver()); }),
            path + ": model 'flat' link 'link' collision mesh 'box.stl': <scale> '1 1 0' must be "
                   "finite and non-zero");
}

TEST_F(MeshWorld, FinelyFacetedMeshIsReducedAndStillRestsOnItsFlatFace) {
  // 200 facets: 400 points, more than a hull keeps, so btShapeHull reduces it; the reduced
  // hull keeps points of both end faces, so the drum stands on its end at z = length / 2.
  bullet_sim_test::writeBinaryStl(dir_ + "/drum.stl",
                                  bullet_sim_test::cylinderTriangles(0.1, 0.3, 200));
  const std::string urdf =
      "<robot name='drum'><link name='base_link'><collision><geometry><mesh filename='" + dir_ +
      "/drum.stl'/></geometry></collision><inertial><mass value='1'/><inertia ixx='0.01' "
      "ixy='0' ixz='0' iyy='0.01' iyz='0' izz='0.005'/></inertial></link></robot>";
  RobotSpec burger = bullet_sim_test::burgerSpec();
  burger.rays[0].noise_stddev_m = 0;
  burger.rays[0].range_resolution_m = 0;
  Simulation sim(bullet_sim_test::flatWorld(), SimConfig());
  Pose3 pose;
  pose.position.z() = 0.4;
  sim.spawnRobot("drum", parseRobot(urdf, "drum", plainResolver()), pose);
  Pose3 burger_pose;
  burger_pose.position.x() = -1.0;
  sim.spawnRobot("burger", burger, burger_pose);
  run(&sim, 2.0);
  const Pose3 rest = sim.modelPose("drum");
  EXPECT_NEAR(rest.position.z(), 0.15, 0.002);
  // Upright: its axis within 0.01 rad of vertical. (Landing on the hull's end polygon may
  // turn it about that axis; that is no tilt.)
  EXPECT_LT(std::acos(std::min(1.0, (rest.orientation * Vector3d::UnitZ()).z())), 0.01);
  // Still round: the lidar finds its side at its radius, 0.1 m from its axis.
  Vector3d lidar;
  for (const LinkPose& link : sim.linkPoses("burger"))
    if (link.link == "base_scan") lidar = link.pose.position;
  const LaserScanData scan = sim.readRay("burger", 0);
  EXPECT_NEAR(scan.ranges[0], rest.position.x() - 0.1 - lidar.x(), 0.001);
}
