// A robot deleted and spawned again under the same name is drawn as the new one. The copy
// of a spec shares its parsed URDF, so a cache that knew a robot by that address kept
// drawing the old look; the camera knows robots by their spawn generation.
#include <gtest/gtest.h>

#include <cmath>

#include "../core/burger.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/simulation.h"

namespace {

using namespace bullet_sim;

// The Burger's camera: 640 x 480, hfov 1.5707, at (0.02, 0, 0.305) from base_footprint.
constexpr int kWidth = 640, kHeight = 480;
constexpr double kHfov = 1.5707;
constexpr double kCameraX = 0.02, kCameraZ = 0.305;

/// One visual: a red box of side 0.2 m centred on the link.
const char* kRedBoxUrdf = R"(<robot name="target">
  <link name="body">
    <visual><geometry><box size="0.2 0.2 0.2"/></geometry>
      <material name="red"><color rgba="1 0 0 1"/></material></visual>
  </link>
</robot>)";

Eigen::Vector3i rgbAt(const ImageData& image, int col, int row) {
  const size_t i = static_cast<size_t>(row) * image.step + 3 * static_cast<size_t>(col);
  return Eigen::Vector3i(image.data[i], image.data[i + 1], image.data[i + 2]);
}

void expectColour(const ImageData& image, int col, int row, const Eigen::Vector3d& expected) {
  const Eigen::Vector3i got = rgbAt(image, col, row);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(got[c], expected[c], 1.0) << "pixel " << col << " " << row << ": "
                                          << got.transpose();
  }
}

}  // namespace

TEST(CameraRespawn, ARobotSpawnedAgainUnderItsNameIsDrawnAsTheNewOne) {
  const WorldSpec free_space;  // no shapes; default light and ambient 0.4
  Simulation sim(free_space, SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  Pose3 ahead;  // on the optical axis, 1 m ahead of the base
  ahead.position = {1.0, 0, kCameraZ};
  const RobotSpec red_box = parseRobot(kRedBoxUrdf, "target.urdf");
  sim.spawnRobot("target", red_box, ahead);
  CameraRenderer renderer(sim);
  ImageData before;
  renderer.render("burger", 0, &before);

  // Faces turned to the camera (normal -x) are turned from the light (direction
  // -0.5 0.1 -0.9: cos < 0), so they show colour * ambient 0.4: 0.4 * 255 = 102. The sky
  // is 0.7 * 255 = 178.5.
  const Eigen::Vector3d red(102, 0, 0), blue(0, 0, 102), sky(178.5, 178.5, 178.5);
  const double f = (kWidth / 2.0) / std::tan(kHfov / 2.0);  // 320.03 px
  const int centre_col = kWidth / 2, row = kHeight / 2;
  // The box's front face, 1.0 - 0.1 - 0.02 = 0.88 m from the camera, is f * 0.1 / 0.88 =
  // 36 px wide either side; the ball below (r 0.05, 0.98 m away) is
  // f * tan(asin(0.05 / 0.98)) = 16 px wide. Column +27 is on the box and off the ball.
  const int side_col = centre_col + 27;
  ASSERT_GT(f * 0.1 / (1.0 - 0.1 - kCameraX), 27 + 2);
  ASSERT_LT(f * std::tan(std::asin(0.05 / (1.0 - kCameraX))), 27 - 2);
  expectColour(before, centre_col, row, red);
  expectColour(before, side_col, row, red);

  const int old_generation = sim.spawnGeneration("target");
  ASSERT_TRUE(sim.deleteRobot("target"));
  RobotSpec blue_ball = red_box;  // same parsed URDF, another look
  blue_ball.visuals.at(0).geometry() = Geometry::sphere(0.05);
  blue_ball.visuals.at(0).rgba = Eigen::Vector4f(0, 0, 1, 1);
  ASSERT_EQ(blue_ball.urdf.get(), red_box.urdf.get());
  sim.spawnRobot("target", blue_ball, ahead);
  EXPECT_NE(sim.spawnGeneration("target"), old_generation);
  ImageData after;
  renderer.render("burger", 0, &after);
  expectColour(after, centre_col, row, blue);
  expectColour(after, side_col, row, sky);
}
