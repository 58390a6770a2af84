// The camera draws movable world models and Gazebo material scripts in their colours: a
// Gazebo/Red crate (a movable model, drawn as a robot) and a static Gazebo/Grey block in
// front of the Burger, at the pixels their geometry projects to.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../core/burger.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/simulation.h"

namespace {

using namespace bullet_sim;

constexpr int kWidth = 640, kHeight = 480;
constexpr double kHfov = 1.5707;
// base_footprint -> camera_link: (0.02, 0, 0.010 + 0.295).
constexpr double kCameraX = 0.02, kCameraZ = 0.305;

std::string block(const std::string& name, bool is_static, double x, double y,
                  const std::string& script) {
  return "<model name='" + name + "'><static>" + (is_static ? "true" : "false") +
         "</static><pose>" + std::to_string(x) + " " + std::to_string(y) +
         " 0.1 0 0 0</pose><link name='link'><inertial><mass>1</mass><inertia><ixx>0.0067</ixx>"
         "<iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial><collision name='c'><geometry>"
         "<box><size>0.2 0.2 0.2</size></box></geometry></collision><visual name='v'><geometry>"
         "<box><size>0.2 0.2 0.2</size></box></geometry><material><script>"
         "<uri>file://media/materials/scripts/gazebo.material</uri><name>" + script +
         "</name></script></material></visual></link></model>";
}

/// Pixel of a point on a face at distance x ahead of the camera, y left of it, height z.
Eigen::Vector2i pixelOf(double x, double y, double z) {
  const double f = (kWidth / 2.0) / std::tan(kHfov / 2.0);
  const double dx = x - kCameraX;
  return Eigen::Vector2i(static_cast<int>(std::lround(kWidth / 2.0 - f * y / dx)),
                         static_cast<int>(std::lround(kHeight / 2.0 - f * (z - kCameraZ) / dx)));
}

Eigen::Vector3i rgbAt(const ImageData& image, const Eigen::Vector2i& px) {
  const size_t i = static_cast<size_t>(px.y() * image.step + px.x() * 3);
  return Eigen::Vector3i(image.data[i], image.data[i + 1], image.data[i + 2]);
}

}  // namespace

TEST(CameraWorldModels, MaterialScriptsAndMovableModelsAreDrawnInTheirColours) {
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'><include><uri>model://sun</uri></include>"
      "<include><uri>model://ground_plane</uri></include>" +
          block("crate", false, 1.0, 0.0, "Gazebo/Red") +
          block("block", true, 1.0, -0.5, "Gazebo/Grey") + "</world></sdf>",
      "w", UriResolver(ResourcePaths{}));
  Simulation sim(world, SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  for (int i = 0; i < 300; ++i) sim.step();  // the crate settles on the ground
  ASSERT_NEAR(sim.modelPose("crate").position.z(), 0.1, 0.002);
  CameraRenderer renderer(sim);
  ImageData image;
  renderer.render("burger", 0, &image);
  ASSERT_EQ(image.encoding, "rgb8");

  // Front faces at x 0.9, 0.1 m off their centres' lines, 0.12 m up.
  const Eigen::Vector3i red = rgbAt(image, pixelOf(0.9, 0.0, 0.12));
  EXPECT_GT(red.x(), 60) << red.transpose();
  EXPECT_LT(red.y(), red.x() / 4) << red.transpose();
  EXPECT_LT(red.z(), red.x() / 4) << red.transpose();
  const Eigen::Vector3i grey = rgbAt(image, pixelOf(0.9, -0.5, 0.12));
  EXPECT_GT(grey.x(), 60) << grey.transpose();  // not black, as before material scripts
  EXPECT_NEAR(grey.x(), grey.y(), 2) << grey.transpose();
  EXPECT_NEAR(grey.x(), grey.z(), 2) << grey.transpose();
}

TEST(CameraWorldModels, ASpawnedStaticModelIsDrawnInItsColourUntilDeleted) {
  // The static Gazebo/Red block (its <model> is the world file's, spawned alone) 1 m ahead.
  Simulation sim(loadWorldString("<sdf version='1.6'><world name='w'><include>"
                                 "<uri>model://sun</uri></include><include>"
                                 "<uri>model://ground_plane</uri></include></world></sdf>",
                                 "w", UriResolver(ResourcePaths{})),
                 SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  const RobotSpec spec =
      parseSdfModelString("<sdf version='1.6'>" + block("sign", true, 0, 0, "Gazebo/Red") +
                              "</sdf>",
                          "spawn_sdf_model", UriResolver(ResourcePaths{}));
  ASSERT_TRUE(spec.is_static);
  Pose3 at;
  at.position = Eigen::Vector3d(1.0, 0.0, 0.1);
  sim.spawnRobot("sign", spec, at);
  for (int i = 0; i < 300; ++i) sim.step();
  EXPECT_TRUE(sim.modelPose("sign").position.isApprox(at.position, 1e-12));
  CameraRenderer renderer(sim);
  ImageData image;
  renderer.render("burger", 0, &image);
  const Eigen::Vector3i red = rgbAt(image, pixelOf(0.9, 0.0, 0.12));
  EXPECT_GT(red.x(), 60) << red.transpose();
  EXPECT_LT(red.y(), red.x() / 4) << red.transpose();
  EXPECT_LT(red.z(), red.x() / 4) << red.transpose();
  ASSERT_TRUE(sim.deleteRobot("sign"));
  renderer.render("burger", 0, &image);
  const Eigen::Vector3i after = rgbAt(image, pixelOf(0.9, 0.0, 0.12));
  EXPECT_LT(std::abs(after.x() - after.y()), 10) << after.transpose();  // the grey ground
}
