// World markers: the round track's walls against DESIGN.md's wall table, every shape
// kind, a movable model's visuals at given link poses, and change detection.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/render/world_marker_set.h"
#include "bullet_sim/render/world_markers.h"
#include "bullet_sim/simulation.h"
#include "burger.h"
#include "mesh_fixtures.h"
#include "round_track.h"

using namespace bullet_sim;

namespace {

constexpr double kMm = 1e-3;

const MarkerShape* find(const std::vector<MarkerShape>& markers, const std::string& ns, int id) {
  for (const MarkerShape& m : markers)
    if (m.ns == ns && m.id == id) return &m;
  return nullptr;
}

Eigen::Vector3d worldPoint(const MarkerShape& m, const Eigen::Vector3d& local) {
  return m.pose.position + m.pose.orientation * local;
}

std::string oneModelWorld(const std::string& pose, const std::string& geometry) {
  return "<sdf version='1.6'><world name='w'><model name='m'><static>true</static><pose>" +
         pose + "</pose><link name='l'><visual name='v'><geometry>" + geometry +
         "</geometry><material><diffuse>0.1 0.2 0.3 0.4</diffuse></material></visual>"
         "</link></model></world></sdf>";
}

MarkerShape onlyMarker(const std::string& pose, const std::string& geometry) {
  const std::vector<MarkerShape> markers =
      worldShapeMarkers(loadWorldString(oneModelWorld(pose, geometry), "test world"));
  EXPECT_EQ(markers.size(), 1u);
  return markers.empty() ? MarkerShape{} : markers[0];
}

}  // namespace

TEST(WorldMarkers, RoundTrackHasOneMarkerPerWallWhereTheTableSays) {
  const std::vector<MarkerShape> markers =
      worldShapeMarkers(loadWorldFile(bullet_sim_test::roundTrackPath()));
  const auto& walls = bullet_sim_test::roundTrackWalls();
  // 21 walls, the ground plane and the start line.
  ASSERT_EQ(markers.size(), walls.size() + 2);
  for (size_t i = 0; i < walls.size(); ++i) {
    const std::string ns = (i < 10 ? "wall_0" : "wall_") + std::to_string(i);
    SCOPED_TRACE(ns);
    const MarkerShape* m = find(markers, ns, 0);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(find(markers, ns, 1), nullptr);
    const auto& w = walls[i];
    EXPECT_EQ(m->type, MarkerShape::Cube);
    EXPECT_NEAR(m->scale_m.x(), bullet_sim_test::kWallThicknessM, kMm);
    EXPECT_NEAR(m->scale_m.y(), w.length, kMm);
    EXPECT_NEAR(m->scale_m.z(), bullet_sim_test::kWallHeightM, kMm);
    // Both ends of the wall's top edge, computed from the table by hand.
    const Eigen::Vector3d along(-std::sin(w.yaw), std::cos(w.yaw), 0);
    const Eigen::Vector3d centre_top(w.x, w.y, bullet_sim_test::kWallHeightM);
    for (double side : {-1.0, 1.0}) {
      const Eigen::Vector3d expected = centre_top + side * 0.5 * w.length * along;
      const Eigen::Vector3d local(0, side * 0.5 * m->scale_m.y(), 0.5 * m->scale_m.z());
      EXPECT_LT((worldPoint(*m, local) - expected).norm(), kMm);
    }
    EXPECT_NEAR(m->rgba[0], 0.57, 1e-6);
    EXPECT_NEAR(m->rgba[1], 0.417, 1e-6);
    EXPECT_NEAR(m->rgba[2], 0.25, 1e-6);
    EXPECT_NEAR(m->rgba[3], 1.0, 1e-6);
  }
}

TEST(WorldMarkers, GroundPlaneIsAThinBoxJustBelowTheGrid) {
  const std::vector<MarkerShape> markers =
      worldShapeMarkers(loadWorldFile(bullet_sim_test::roundTrackPath()));
  const MarkerShape* ground = find(markers, "ground_plane", 0);
  ASSERT_NE(ground, nullptr);
  EXPECT_EQ(ground->type, MarkerShape::Cube);
  EXPECT_TRUE(ground->scale_m.isApprox(Eigen::Vector3d(100, 100, 0.002)));
  // Top face 2 mm under z = 0, so the box centre is 3 mm under it.
  EXPECT_TRUE(ground->pose.position.isApprox(Eigen::Vector3d(0, 0, -0.003)));
  EXPECT_NEAR(ground->rgba[0], 0.5, 1e-6);

  const MarkerShape* line = find(markers, "start_line", 0);
  ASSERT_NE(line, nullptr);
  EXPECT_TRUE(line->scale_m.isApprox(Eigen::Vector3d(0.015, 1.5, 0.015)));
  EXPECT_LT((line->pose.position - Eigen::Vector3d(-0.1, 0.333, 0.022)).norm(), 1e-9);
  EXPECT_TRUE(line->rgba.isApprox(Eigen::Vector4f(1, 1, 1, 1)));
}

TEST(WorldMarkers, CylinderAndSphereScalesAreDiameters) {
  const MarkerShape cylinder =
      onlyMarker("1 2 3 0 0 0", "<cylinder><radius>0.2</radius><length>1.5</length></cylinder>");
  EXPECT_EQ(cylinder.type, MarkerShape::Cylinder);
  EXPECT_TRUE(cylinder.scale_m.isApprox(Eigen::Vector3d(0.4, 0.4, 1.5)));
  EXPECT_TRUE(cylinder.pose.position.isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(cylinder.rgba.isApprox(Eigen::Vector4f(0.1f, 0.2f, 0.3f, 0.4f)));
  EXPECT_EQ(cylinder.ns, "m");

  const MarkerShape sphere = onlyMarker("0 0 1 0 0 0", "<sphere><radius>0.1</radius></sphere>");
  EXPECT_EQ(sphere.type, MarkerShape::Sphere);
  EXPECT_TRUE(sphere.scale_m.isApprox(Eigen::Vector3d(0.2, 0.2, 0.2)));
}

TEST(WorldMarkers, TiltedPlaneBoxLiesAlongItsNormal) {
  // A wall-like plane: normal +x, 2 x 3 m, at x = 5.
  const MarkerShape plane = onlyMarker(
      "5 0 1 0 0 0", "<plane><normal>1 0 0</normal><size>2 3</size></plane>");
  EXPECT_EQ(plane.type, MarkerShape::Cube);
  EXPECT_TRUE(plane.scale_m.isApprox(Eigen::Vector3d(2, 3, 0.002)));
  EXPECT_LT((plane.pose.orientation * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(),
            1e-9);
  // The top face (local z = +thickness/2) is 2 mm behind the plane along its normal.
  const Eigen::Vector3d top = worldPoint(plane, Eigen::Vector3d(0, 0, 0.001));
  EXPECT_LT((top - Eigen::Vector3d(4.998, 0, 1)).norm(), 1e-9);
}

TEST(WorldMarkers, PlaneWithoutSizeBecomesALargeSquare) {
  const MarkerShape plane =
      onlyMarker("0 0 0 0 0 0", "<plane><normal>0 0 1</normal><size>0 0</size></plane>");
  EXPECT_TRUE(plane.scale_m.isApprox(Eigen::Vector3d(100, 100, 0.002)));
  PlaneDrawing small;
  small.infinite_plane_side_m = 7;
  const auto markers = worldShapeMarkers(
      loadWorldString(oneModelWorld("0 0 0 0 0 0",
                                    "<plane><normal>0 0 1</normal><size>0 0</size></plane>"),
                      "test world"),
      small);
  ASSERT_EQ(markers.size(), 1u);
  EXPECT_DOUBLE_EQ(markers[0].scale_m.x(), 7);
}

TEST(WorldMarkers, ModelVisualsFollowTheirLinks) {
  const RobotSpec spec = parseRobot(R"(<robot name="crate">
    <material name="red"><color rgba="1 0 0 1"/></material>
    <link name="body">
      <visual><origin xyz="0.1 0 0.05"/><geometry><box size="0.2 0.3 0.1"/></geometry>
        <material name="red"/></visual>
      <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    <link name="knob">
      <visual><geometry><sphere radius="0.02"/></geometry></visual>
      <inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    </link>
    <joint name="knob_joint" type="fixed"><parent link="body"/><child link="knob"/>
      <origin xyz="0 0 0.2"/></joint>
  </robot>)",
                                    "crate");
  Pose3 body;
  body.position = {1, 2, 0};
  body.orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  // Only the body's pose is given: the knob's visual is left out.
  const std::vector<MarkerShape> markers = modelMarkers("crate", spec, {{"body", body}});
  ASSERT_EQ(markers.size(), 1u);
  const MarkerShape& box = markers[0];
  EXPECT_EQ(box.ns, "crate");
  EXPECT_EQ(box.type, MarkerShape::Cube);
  EXPECT_TRUE(box.scale_m.isApprox(Eigen::Vector3d(0.2, 0.3, 0.1)));
  // The visual's +0.1 m along the body's x points along world +y after the 90 deg turn.
  EXPECT_LT((box.pose.position - Eigen::Vector3d(1, 2.1, 0.05)).norm(), 1e-9);
  EXPECT_TRUE(box.rgba.isApprox(Eigen::Vector4f(1, 0, 0, 1)));

  Pose3 knob;
  knob.position = {1, 2, 0.2};
  const auto both = modelMarkers("crate", spec, {{"body", body}, {"knob", knob}});
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[1].type, MarkerShape::Sphere);
  EXPECT_TRUE(both[1].scale_m.isApprox(Eigen::Vector3d(0.04, 0.04, 0.04)));
}

TEST(WorldMarkers, ChangesReportNewMovedAndRecolouredMarkersOnly) {
  MarkerChanges changes(0.001, 0.001);
  MarkerShape a, b;
  a.ns = "box";
  b.ns = "box";
  b.id = 1;
  EXPECT_EQ(changes.update({a, b}).size(), 2u);
  EXPECT_TRUE(changes.update({a, b}).empty());

  a.pose.position.x() += 0.0005;  // under the tolerance: not a change
  EXPECT_TRUE(changes.update({a, b}).empty());
  a.pose.position.x() += 0.002;
  const auto moved = changes.update({a, b});
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0].id, 0);

  b.pose.orientation = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ());
  ASSERT_EQ(changes.update({a, b}).size(), 1u);
  b.rgba[0] = 0.1f;
  ASSERT_EQ(changes.update({a, b}).size(), 1u);
  EXPECT_TRUE(changes.update({a, b}).empty());
}

namespace {

const char* kCrate = R"(<robot name="crate">
  <link name="body">
    <visual><geometry><box size="0.2 0.2 0.1"/></geometry></visual>
    <collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision>
    <inertial><mass value="1"/><inertia ixx="0.004" ixy="0" ixz="0" iyy="0.004" iyz="0" izz="0.007"/></inertial>
  </link>
</robot>)";

const MarkerShape* crateMarker(const std::vector<MarkerShape>& markers) {
  return find(markers, "crate", 0);
}

}  // namespace

TEST(WorldMarkerSet, RepublishesWhenATrackedModelMoves) {
  const WorldSpec world = bullet_sim_test::flatWorld();
  Simulation sim(world, SimConfig{});
  Pose3 start;
  start.position = {0, 0, 0.5};
  sim.spawnRobot("crate", parseRobot(kCrate, "crate"), start);
  WorldMarkerSet set(world);
  set.track("crate");

  auto first = set.update(sim);
  ASSERT_TRUE(first.has_value());
  ASSERT_EQ(first->size(), world.shapes.size() + 1);
  ASSERT_NE(crateMarker(*first), nullptr);
  EXPECT_NEAR(crateMarker(*first)->pose.position.z(), 0.5, 1e-9);
  EXPECT_FALSE(set.update(sim).has_value());  // nothing moved

  // Falling: after 0.2 s the crate is 0.5 g t^2 = 0.196 m lower, and redrawn there.
  for (int i = 0; i < 200; ++i) sim.step();
  auto falling = set.update(sim);
  ASSERT_TRUE(falling.has_value());
  EXPECT_NEAR(crateMarker(*falling)->pose.position.z(), 0.5 - 0.5 * 9.8 * 0.2 * 0.2, 0.01);

  // At rest on the ground (centre at half its height), it is not sent again.
  for (int i = 0; i < 2000; ++i) sim.step();
  auto resting = set.update(sim);
  if (resting) {
    EXPECT_NEAR(crateMarker(*resting)->pose.position.z(), 0.05, 0.005);
  }
  for (int i = 0; i < 100; ++i) sim.step();
  EXPECT_FALSE(set.update(sim).has_value());

  Pose3 moved;
  moved.position = {1, 2, 0.05};
  sim.setModelState("crate", moved, Twist3{});
  auto teleported = set.update(sim);
  ASSERT_TRUE(teleported.has_value());
  EXPECT_LT((crateMarker(*teleported)->pose.position - moved.position).norm(), 1e-6);

  // A deleted model's markers go with the next set.
  sim.deleteRobot("crate");
  auto without = set.update(sim);
  ASSERT_TRUE(without.has_value());
  EXPECT_EQ(without->size(), world.shapes.size());
  EXPECT_EQ(crateMarker(*without), nullptr);
}

TEST(WorldMarkerSet, EveryModelButTheExceptedIsDrawnSpawnedLaterIncluded) {
  // The spawned models' set: no world shapes, every robot the simulation has but those
  // excepted, as Gazebo's window shows them (a robot without a robot_state_publisher too).
  const WorldSpec world = bullet_sim_test::flatWorld();
  Simulation sim(world, SimConfig{});
  Pose3 start;
  start.position = {0, 0, 0.05};
  sim.spawnRobot("crate", parseRobot(kCrate, "crate"), start);
  WorldMarkerSet models{WorldSpec()};
  models.trackEveryModelBut({"crate"});
  auto first = models.update(sim);
  ASSERT_TRUE(first.has_value());
  EXPECT_TRUE(first->empty());  // the crate is excepted
  EXPECT_FALSE(models.update(sim).has_value());
  start.position = {2, 0, 0.05};
  sim.spawnRobot("second", parseRobot(kCrate, "second"), start);
  auto spawned = models.update(sim);
  ASSERT_TRUE(spawned.has_value());
  ASSERT_EQ(spawned->size(), 1u);
  EXPECT_EQ(spawned->front().ns, "second");
  EXPECT_NEAR(spawned->front().pose.position.x(), 2, 1e-9);
  sim.deleteRobot("second");
  auto deleted = models.update(sim);
  ASSERT_TRUE(deleted.has_value());
  EXPECT_TRUE(deleted->empty());
}

TEST(WorldMarkerSet, WithoutTrackedModelsTheWorldIsSentOnce) {
  const WorldSpec world = bullet_sim_test::flatWorld();
  Simulation sim(world, SimConfig{});
  WorldMarkerSet set(world);
  auto first = set.update(sim);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->size(), world.shapes.size());
  sim.step();
  EXPECT_FALSE(set.update(sim).has_value());
}

TEST(WorldMarkers, MeshVisualsAreMeshResourcesAtTheirScale) {
  const std::string dir = bullet_sim_test::makeTempDir();
  bullet_sim_test::writeBinaryStl(dir + "/crate.stl",
                                  bullet_sim_test::boxTriangles({0.2, 0.2, 0.2}));
  const MarkerShape m =
      onlyMarker("1 2 0 0 0 0.5", "<mesh><uri>file://" + dir +
                                      "/crate.stl</uri><scale>2 1 0.5</scale></mesh>");
  EXPECT_EQ(m.type, MarkerShape::Mesh);
  EXPECT_EQ(m.mesh_resource, "file://" + dir + "/crate.stl");
  EXPECT_TRUE(m.scale_m.isApprox(Eigen::Vector3d(2, 1, 0.5)));
  EXPECT_NEAR(m.pose.position.x(), 1, 1e-9);
  EXPECT_NEAR(m.pose.position.y(), 2, 1e-9);
  EXPECT_TRUE(m.rgba.isApprox(Eigen::Vector4f(0.1f, 0.2f, 0.3f, 0.4f)));
}

TEST(WorldMarkers, AnUnreadableMeshVisualIsLeftOut) {
  const std::vector<MarkerShape> markers = worldShapeMarkers(loadWorldString(
      oneModelWorld("0 0 0 0 0 0", "<mesh><uri>file:///nonexistent/crate.stl</uri></mesh>"),
      "test world"));
  EXPECT_TRUE(markers.empty());
}
