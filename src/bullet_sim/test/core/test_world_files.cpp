// Worlds as Gazebo saves them: <state> poses, model:// includes with model.config, the
// built-in sun and ground_plane, material scripts; one fixture or generated folder per
// failure mode with the message asserted.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "load_errors.h"
#include "round_track.h"
#include "temp_dir.h"

using namespace bullet_sim;
using bullet_sim_test::TempDir;

using bullet_sim_test::fixture;
using bullet_sim_test::loadErrorOf;

namespace {

const UriResolver kNoPaths{ResourcePaths{}};

const StaticShape* shapeOf(const WorldSpec& world, const std::string& model, bool collides = true) {
  for (const StaticShape& s : world.shapes) {
    if (s.model == model && s.collides == collides) return &s;
  }
  return nullptr;
}

double yawOf(const Pose3& p) {
  const Eigen::Vector3d x = p.orientation * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}

/// The range the Burger's lidar reads at `angle_rad` (nearest sample).
double rangeAt(const LaserScanData& scan, double angle_rad) {
  const int i = static_cast<int>(std::lround((angle_rad - scan.angle_min) / scan.angle_increment));
  return scan.ranges.at(static_cast<size_t>(i));
}

/// A model folder `name` under models/ with a model.config naming `config_body` entries.
void writeModel(const TempDir& dir, const std::string& name, const std::string& config_body) {
  dir.write("models/" + name + "/model.config",
            "<?xml version=\"1.0\"?>\n<model><name>" + name + "</name>" + config_body + "</model>\n");
}

std::string boxModelSdf(const std::string& version, const std::string& name, double size,
                        const std::string& script) {
  const std::string s = std::to_string(size);
  return "<?xml version=\"1.0\"?><sdf version=\"" + version + "\"><model name=\"" + name +
         "\"><link name=\"link\"><collision name=\"c\"><geometry><box><size>" + s + " " + s +
         " " + s + "</size></box></geometry></collision><visual name=\"v\"><geometry><box><size>" +
         s + " " + s + " " + s + "</size></box></geometry><material><script>"
         "<uri>file://media/materials/scripts/gazebo.material</uri><name>" +
         script + "</name></script></material></visual></link></model></sdf>";
}

}  // namespace

// ---------------------------------------------------------------- <state> ----

TEST(WorldState, SavedPosesPlaceTheWalls) {
  const WorldSpec world = loadWorldFile(fixture("world_state.world"), kNoPaths);
  const StaticShape* east = shapeOf(world, "wall_east");
  ASSERT_NE(east, nullptr);
  EXPECT_TRUE(east->pose.position.isApprox(Eigen::Vector3d(2, 0, 0.25), 1e-9));
  const StaticShape* west = shapeOf(world, "wall_west");
  ASSERT_NE(west, nullptr);
  // The saved link pose wins over the saved model pose (0 3 0.25).
  EXPECT_TRUE(west->pose.position.isApprox(Eigen::Vector3d(-3, 0, 0.25), 1e-9));
  EXPECT_NEAR(yawOf(west->pose), M_PI / 2, 1e-9);
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
}

TEST(WorldState, LidarSeesTheWallsWhereTheStatePutsThem) {
  Simulation sim(loadWorldFile(fixture("world_state.world"), kNoPaths), SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  sim.step();
  const LaserScanData scan = sim.readRay("burger", 0);
  // The lidar sits 0.032 m behind the robot's origin; walls are 0.1 m thick.
  EXPECT_NEAR(rangeAt(scan, 0.0), 2.0 - 0.05 + 0.032, 0.03);   // east wall at x 2, not 1
  EXPECT_NEAR(rangeAt(scan, M_PI), 3.0 - 0.05 - 0.032, 0.03);  // west wall at x -3
  // Where wall_west was written (y 1) there is nothing now.
  EXPECT_TRUE(std::isinf(rangeAt(scan, M_PI / 2))) << rangeAt(scan, M_PI / 2);
}

TEST(WorldState, StateOfAModelTheWorldLacksIsAWarning) {
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'><include><uri>model://ground_plane</uri></include>"
      "<state world_name='w'><model name='ghost'><pose>1 0 0 0 0 0</pose></model></state>"
      "</world></sdf>",
      "w.world", kNoPaths);
  ASSERT_EQ(world.warnings.size(), 1u);
  EXPECT_EQ(world.warnings[0],
            "w.world: <state> <model name=\"ghost\">: the world has no such model: its state "
            "is ignored");
}

TEST(WorldState, NonNumericSavedPoseNamesModelLinkAndValue) {
  const std::string path = fixture("world_state_bad_pose.world");
  const std::string error = loadErrorOf([&] { loadWorldFile(path, kNoPaths); });
  EXPECT_EQ(error, path + ": <state> <model name=\"wall\"> <link name=\"link\"> <pose>: "
                          "'2 zero 0.25 0 0 0' is not 'x y z roll pitch yaw'");
}

// --------------------------------------------------------------- includes ----

TEST(WorldIncludes, SunAndGroundPlaneAreBuiltIn) {
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'><include><uri>model://sun</uri></include>"
      "<include><uri>model://ground_plane</uri></include></world></sdf>",
      "w", kNoPaths);
  ASSERT_EQ(world.shapes.size(), 1u);
  EXPECT_EQ(world.shapes[0].kind, StaticShape::Plane);
  EXPECT_EQ(world.shapes[0].model, "ground_plane");
  EXPECT_TRUE(world.shapes[0].normal.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(world.shapes[0].rgba[0], 0.7, 1e-6);  // Gazebo/Grey
  EXPECT_TRUE(world.light_direction.isApprox(Eigen::Vector3d(-0.5, 0.1, -0.9).normalized(), 1e-9));
  EXPECT_TRUE(world.models.empty());
}

TEST(WorldIncludes, ModelFolderWithHighestReadableSdfVersionNamePoseAndStatic) {
  TempDir dir;
  // 1.10 is newer than the reader reads (1.9): numerically, not as text.
  writeModel(dir, "crate",
             "<sdf version=\"1.4\">old.sdf</sdf><sdf version=\"1.6\">model.sdf</sdf>"
             "<sdf version=\"1.10\">future.sdf</sdf>");
  dir.write("models/crate/old.sdf", boxModelSdf("1.4", "crate", 1.0, "Gazebo/Blue"));
  dir.write("models/crate/model.sdf", boxModelSdf("1.6", "crate", 0.4, "Gazebo/Red"));
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'>"
      "<include><uri>model://crate</uri><name>crate_a</name><pose>1 2 0.2 0 0 0.5</pose>"
      "<static>true</static></include>"
      "<include><uri>model://crate</uri><name>crate_b</name><pose>3 0 0.2 0 0 0</pose>"
      "<static>true</static></include></world></sdf>",
      "w", UriResolver(ResourcePaths{{dir.sub("models")}, {}}));
  const StaticShape* a = shapeOf(world, "crate_a");
  const StaticShape* b = shapeOf(world, "crate_b");
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(a->size.isApprox(Eigen::Vector3d::Constant(0.4)));
  EXPECT_TRUE(a->pose.position.isApprox(Eigen::Vector3d(1, 2, 0.2)));
  EXPECT_NEAR(yawOf(a->pose), 0.5, 1e-9);
  EXPECT_TRUE(b->pose.position.isApprox(Eigen::Vector3d(3, 0, 0.2)));
  EXPECT_TRUE(a->rgba.isApprox(Eigen::Vector4f(1, 0, 0, 1)));  // Gazebo/Red
  EXPECT_TRUE(world.models.empty());
}

TEST(WorldIncludes, AModelFolderOnThePathWinsOverTheBuiltInGroundPlane) {
  TempDir dir;
  writeModel(dir, "ground_plane", "<sdf version=\"1.6\">model.sdf</sdf>");
  dir.write("models/ground_plane/model.sdf",
            "<sdf version='1.6'><model name='ground_plane'><static>true</static>"
            "<link name='link'><collision name='c'><geometry><box><size>10 10 0.1</size></box>"
            "</geometry></collision></link></model></sdf>");
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'><include><uri>model://ground_plane</uri></include>"
      "</world></sdf>",
      "w", UriResolver(ResourcePaths{{dir.sub("models")}, {}}));
  ASSERT_EQ(world.shapes.size(), 1u);
  EXPECT_EQ(world.shapes[0].kind, StaticShape::Box);
}

TEST(WorldIncludes, ModelFoldersInsideAFolderOfModels) {
  // model://set/part, as TurtleBot3's autorace worlds include their parts.
  TempDir dir;
  writeModel(dir, "set/part", "<sdf version=\"1.6\">model.sdf</sdf>");
  dir.write("models/set/part/model.sdf", boxModelSdf("1.6", "part", 0.3, "Gazebo/Green"));
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'><include><uri>model://set/part</uri>"
      "<static>true</static></include></world></sdf>",
      "w", UriResolver(ResourcePaths{{dir.sub("models")}, {}}));
  ASSERT_NE(shapeOf(world, "part"), nullptr);
  EXPECT_TRUE(shapeOf(world, "part")->rgba.isApprox(Eigen::Vector4f(0, 1, 0, 1)));
}

TEST(WorldIncludes, StaticLinkWithNanInertiaLoads) {
  // Gazebo saves static links with mass 0 and nan moments, and never uses them.
  const std::string path = fixture("world_static_nan_inertia.world");
  const WorldSpec world = loadWorldFile(path, kNoPaths);
  ASSERT_NE(shapeOf(world, "walls"), nullptr);
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
}

TEST(WorldIncludes, MissingModelNamesUriAndFoldersSearched) {
  TempDir dir;
  const std::string path = fixture("world_missing_include.world");
  const UriResolver resolver(ResourcePaths{{dir.sub("a"), dir.sub("b")}, {}});
  const std::string error = loadErrorOf([&] { loadWorldFile(path, resolver); });
  EXPECT_EQ(error, path + ":6: <world name=\"missing_include\"> <include>: "
                          "<uri>model://no_such_model</uri>: model 'no_such_model' "
                          "not found in the model folders (GAZEBO_MODEL_PATH): " +
                       dir.sub("a") + ", " + dir.sub("b") +
                       "; built in are only sun and ground_plane");
}

/// Loads a world including model://crate from a folder whose model.config is `config`.
std::string errorWithModelConfig(const TempDir& dir, const std::string& config) {
  if (!config.empty()) dir.write("models/crate/model.config", config);
  dir.write("models/crate/model.sdf", boxModelSdf("1.6", "crate", 0.4, "Gazebo/Red"));
  return loadErrorOf([&] {
    loadWorldString("<sdf version='1.6'><world name='w'><include><uri>model://crate</uri>"
                    "</include></world></sdf>",
                    "w.world", UriResolver(ResourcePaths{{dir.sub("models")}, {}}));
  });
}

TEST(WorldIncludes, ModelFolderWithoutModelConfig) {
  TempDir dir;
  EXPECT_EQ(errorWithModelConfig(dir, ""),
            "w.world:1: <world name=\"w\"> <include>: <uri>model://crate</uri>: model folder " +
                dir.sub("models/crate") +
                " has no model.config");
}

TEST(WorldIncludes, MalformedModelConfig) {
  TempDir dir;
  const std::string error = errorWithModelConfig(dir, "<model><sdf version='1.6'>model.sdf</sdf>");
  EXPECT_NE(error.find("w.world:1: <world name=\"w\"> <include>: <uri>model://crate</uri>: " +
                       dir.sub("models/crate/model.config") + ": malformed XML: "),
            std::string::npos)
      << error;
}

TEST(WorldIncludes, ModelConfigWithoutReadableSdfVersion) {
  TempDir dir;
  EXPECT_EQ(errorWithModelConfig(dir, "<model><sdf version='2.0'>model.sdf</sdf></model>"),
            "w.world:1: <world name=\"w\"> <include>: <uri>model://crate</uri>: " +
                dir.sub("models/crate/model.config") +
                ": no <sdf version=\"..\"> entry of a version the simulator reads (1.0 to 1.9; "
                "versions given: 2.0)");
}

TEST(WorldIncludes, ModelConfigNamingMissingFile) {
  TempDir dir;
  EXPECT_EQ(errorWithModelConfig(dir, "<model><sdf version='1.6'>crate.sdf</sdf></model>"),
            "w.world:1: <world name=\"w\"> <include>: <uri>model://crate</uri>: " +
                dir.sub("models/crate/model.config") + ": <sdf version=\"1.6\"> names " +
                dir.sub("models/crate/crate.sdf") +
                ", which does not exist");
}

TEST(WorldIncludes, IncludedModelFileWithBadSdfVersion) {
  TempDir dir;
  writeModel(dir, "crate", "<sdf version=\"1.6\">model.sdf</sdf>");
  dir.write("models/crate/model.sdf", boxModelSdf("1.x", "crate", 0.4, "Gazebo/Red"));
  const std::string error = loadErrorOf([&] {
    loadWorldString("<sdf version='1.6'><world name='w'><include><uri>model://crate</uri>"
                    "</include></world></sdf>",
                    "w.world", UriResolver(ResourcePaths{{dir.sub("models")}, {}}));
  });
  EXPECT_EQ(error, "w.world:1: <world name=\"w\"> <include>: <uri>model://crate</uri>: " +
                       dir.sub("models/crate/model.sdf") +
                       ": invalid SDF model: <sdf version=\"1.x\">: not a version number such "
                       "as \"1.6\"");
}

// -------------------------------------------------------------- materials ----

TEST(WorldMaterials, ScriptNamesGiveGazebosColoursAndDiffuseWins) {
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'>"
      "<model name='wood'><static>true</static><pose>0 0 0 0 0 0</pose><link name='l'>"
      "<visual name='v'><geometry><sphere><radius>1</radius></sphere></geometry><material>"
      "<script><uri>file://media/materials/scripts/gazebo.material</uri>"
      "<name>Gazebo/Orange</name></script></material></visual></link></model>"
      "<model name='painted'><static>true</static><pose>0 3 0 0 0 0</pose><link name='l'>"
      "<visual name='v'><geometry><sphere><radius>1</radius></sphere></geometry><material>"
      "<script><uri>file://media/materials/scripts/gazebo.material</uri>"
      "<name>Gazebo/Orange</name></script><diffuse>0 0 1 1</diffuse></material>"
      "</visual></link></model>"
      "<model name='plain'><static>true</static><pose>0 6 0 0 0 0</pose><link name='l'>"
      "<visual name='v'><geometry><sphere><radius>1</radius></sphere></geometry><material>"
      "<ambient>0.2 0.3 0.4 1</ambient></material></visual></link></model>"
      "</world></sdf>",
      "w", kNoPaths);
  EXPECT_TRUE(shapeOf(world, "wood", false)->rgba.isApprox(Eigen::Vector4f(1, 0.5088f, 0.0468f, 1)));
  EXPECT_TRUE(shapeOf(world, "painted", false)->rgba.isApprox(Eigen::Vector4f(0, 0, 1, 1)));
  EXPECT_TRUE(shapeOf(world, "plain", false)->rgba.isApprox(Eigen::Vector4f(0.2f, 0.3f, 0.4f, 1)));
  EXPECT_TRUE(world.warnings.empty());
}

TEST(WorldMaterials, UnknownScriptIsNamedInAWarningAndDrawnGrey) {
  const std::string path = fixture("world_unknown_material.world");
  const WorldSpec world = loadWorldFile(path, kNoPaths);
  ASSERT_EQ(world.warnings.size(), 1u);
  EXPECT_EQ(world.warnings[0], path + ": model 'pillar' link 'link' visual 'visual': material "
                                      "script 'Custom/Marble' is not one of Gazebo's stock "
                                      "materials nor in any script of its <uri>s or "
                                      "GAZEBO_RESOURCE_PATH: drawn grey");
  EXPECT_TRUE(shapeOf(world, "pillar", false)->rgba.isApprox(Eigen::Vector4f(0.7f, 0.7f, 0.7f, 1)));
}

TEST(RobotMaterials, GazeboReferenceMaterialColoursTheLinksVisuals) {
  const RobotSpec spec = parseRobot(R"(<robot name="r">
    <material name="white"><color rgba="1 1 1 1"/></material>
    <link name="base"><visual><geometry><box size="1 1 1"/></geometry><material name="white"/></visual>
      <visual><geometry><sphere radius="0.1"/></geometry></visual></link>
    <link name="arm"><visual><geometry><box size="1 1 1"/></geometry><material name="white"/></visual></link>
    <link name="tip"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
    <joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint>
    <joint name="k" type="fixed"><parent link="arm"/><child link="tip"/></joint>
    <gazebo reference="base"><material>Gazebo/Red</material></gazebo>
    <gazebo reference="tip"><material>Custom/Chrome</material></gazebo>
  </robot>)", "robot_description", kNoPaths);
  int red = 0;
  for (const VisualSpec& v : spec.visuals) {
    if (v.link == "base") {
      EXPECT_TRUE(v.rgba.isApprox(Eigen::Vector4f(1, 0, 0, 1)));
      ++red;
    } else if (v.link == "arm") {
      EXPECT_TRUE(v.rgba.isApprox(Eigen::Vector4f(1, 1, 1, 1)));  // its URDF material
    } else {
      EXPECT_TRUE(v.rgba.isApprox(Eigen::Vector4f(0.7f, 0.7f, 0.7f, 1)));
    }
  }
  EXPECT_EQ(red, 2);
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0], "<gazebo reference=\"tip\"> <material>: 'Custom/Chrome' is not one "
                              "of Gazebo's stock materials: drawn grey");
}

// ------------------------------------------------------ handed-over documents ----

// The documents a load hands over are freed before the spec is used: the walls are still
// where DESIGN.md's table puts them, and the spec is the one a plain load gives.
TEST(WorldDocuments, AWorldOutlivesTheDocumentsItWasReadFrom) {
  const UriResolver resolver(ResourcePaths::fromEnvironment());
  std::shared_ptr<const void> documents;
  const WorldSpec world = loadWorldFile(bullet_sim_test::roundTrackPath(), resolver, &documents);
  EXPECT_NE(documents, nullptr);
  EXPECT_EQ(documents.use_count(), 1);
  documents.reset();
  const auto& walls = bullet_sim_test::roundTrackWalls();
  for (size_t i = 0; i < walls.size(); ++i) {
    const std::string name = (i < 10 ? "wall_0" : "wall_") + std::to_string(i);
    SCOPED_TRACE(name);
    const StaticShape* wall = shapeOf(world, name);
    ASSERT_NE(wall, nullptr);
    EXPECT_EQ(wall->kind, Geometry::Box);
    EXPECT_NEAR(wall->size.x(), bullet_sim_test::kWallThicknessM, 1e-9);
    EXPECT_NEAR(wall->size.y(), walls[i].length, 1e-9);
    EXPECT_NEAR(wall->size.z(), bullet_sim_test::kWallHeightM, 1e-9);
    EXPECT_NEAR(wall->pose.position.x(), walls[i].x, 1e-9);
    EXPECT_NEAR(wall->pose.position.y(), walls[i].y, 1e-9);
    EXPECT_NEAR(wall->pose.position.z(), 0.5 * bullet_sim_test::kWallHeightM, 1e-9);
    EXPECT_NEAR(std::remainder(yawOf(wall->pose) - walls[i].yaw, 2 * M_PI), 0.0, 1e-9);
  }
  const WorldSpec plain = loadWorldFile(bullet_sim_test::roundTrackPath(), resolver);
  EXPECT_EQ(world.name, plain.name);
  ASSERT_EQ(world.shapes.size(), plain.shapes.size());
  for (size_t i = 0; i < plain.shapes.size(); ++i) {
    const StaticShape& a = world.shapes[i];
    const StaticShape& b = plain.shapes[i];
    SCOPED_TRACE(b.model + " " + b.link);
    EXPECT_EQ(a.model, b.model);
    EXPECT_EQ(a.link, b.link);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.size, b.size);
    EXPECT_EQ(a.pose.position, b.pose.position);
    EXPECT_EQ(a.pose.orientation.coeffs(), b.pose.orientation.coeffs());
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_EQ(a.collides, b.collides);
  }
  EXPECT_EQ(world.static_models.size(), plain.static_models.size());
  EXPECT_EQ(world.warnings, plain.warnings);
}

TEST(WorldDocuments, NoneAreHandedOverWhenTheWorldCannotBeLoaded) {
  TempDir dir;
  const std::string path =
      dir.write("broken.world", "<sdf version='1.6'><world name='w'><model name='m'>");
  std::shared_ptr<const void> documents;
  EXPECT_THROW(loadWorldFile(path, kNoPaths, &documents), LoadError);
  EXPECT_EQ(documents, nullptr);
}

// Every <light> of the world reaches the spec in world coordinates: a spot light under a
// yawed frame points where the frame turns its direction, with its attenuation and cone.
TEST(WorldLights, PointAndSpotLightsInWorldCoordinates) {
  const WorldSpec spec = loadWorldString(R"(<sdf version="1.6"><world name="w">
    <light type="directional" name="sun"><direction>0 0.6 -0.8</direction></light>
    <light type="point" name="lamp"><pose>1 2 3 0 0 0</pose>
      <diffuse>0.5 0.5 0.5 1</diffuse>
      <attenuation><range>20</range><constant>0.5</constant><linear>0.01</linear>
        <quadratic>0.001</quadratic></attenuation></light>
    <light type="spot" name="spot"><pose>0 0 2 0 0 1.5707963267948966</pose>
      <direction>1 0 0</direction>
      <spot><inner_angle>0.1</inner_angle><outer_angle>0.5</outer_angle>
        <falloff>1.5</falloff></spot></light>
  </world></sdf>)", "lights.world", kNoPaths);
  ASSERT_EQ(spec.lights.size(), 3u);
  EXPECT_EQ(spec.lights[0].type, "directional");
  EXPECT_NEAR(spec.light_direction.y(), 0.6, 1e-9);
  EXPECT_NEAR(spec.light_direction.z(), -0.8, 1e-9);
  const LightSpec& lamp = spec.lights[1];
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_EQ(lamp.type, "point");
  EXPECT_NEAR((lamp.pose.position - Eigen::Vector3d(1, 2, 3)).norm(), 0, 1e-12);
  EXPECT_FLOAT_EQ(lamp.diffuse.x(), 0.5f);
  EXPECT_DOUBLE_EQ(lamp.range_m, 20);
  EXPECT_DOUBLE_EQ(lamp.constant, 0.5);
  EXPECT_DOUBLE_EQ(lamp.linear, 0.01);
  EXPECT_DOUBLE_EQ(lamp.quadratic, 0.001);
  const LightSpec& spot = spec.lights[2];
  EXPECT_EQ(spot.type, "spot");
  // (1, 0, 0) in a frame yawed 90 degrees is +y in the world.
  EXPECT_NEAR((spot.direction - Eigen::Vector3d(0, 1, 0)).norm(), 0, 1e-9);
  EXPECT_DOUBLE_EQ(spot.spot_inner_rad, 0.1);
  EXPECT_DOUBLE_EQ(spot.spot_outer_rad, 0.5);
  EXPECT_DOUBLE_EQ(spot.spot_falloff, 1.5);
}
