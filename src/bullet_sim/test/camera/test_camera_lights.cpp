// The world's point lights in the Burger's camera, per pixel as Gazebo's OGRE adds them:
// a grey wall 1.475 m ahead of the camera (face at x = 1.475), lit by the ambient 0.1 and
// a point light 0.475 m in front of it at camera height; the sun lights the wall's back.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../core/burger.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/simulation.h"
#include "burger_camera.h"

namespace {

using namespace bullet_sim;
using bullet_sim_test::kCamera;
using bullet_sim_test::kFocal;
using bullet_sim_test::pixel;

constexpr double kFaceX = 1.475, kLightX = 1.0;

/// The wall world with one point light of the given diffuse and attenuation, or none.
WorldSpec wallWorld(const std::string& light) {
  return loadWorldString(
      "<sdf version='1.6'><world name='w'><scene><ambient>0.1 0.1 0.1 1</ambient></scene>"
      "<light name='sun' type='directional'><direction>-1 0 -1</direction></light>" + light +
          "<model name='wall'><static>true</static><pose>1.5 0 0.305 0 0 0</pose>"
          "<link name='l'><visual name='v'><geometry><box><size>0.05 3 3</size></box></geometry>"
          "<material><diffuse>0.5 0.5 0.5 1</diffuse></material></visual></link></model>"
          "</world></sdf>",
      "wall world", UriResolver(ResourcePaths{}));
}

std::string pointLight(double diffuse, double constant, double linear, double quadratic) {
  const std::string d = std::to_string(diffuse);
  return "<light name='lamp' type='point'><pose>" + std::to_string(kLightX) +
         " 0 0.305 0 0 0</pose><diffuse>" + d + " " + d + " " + d +
         " 1</diffuse><attenuation><range>20</range><constant>" + std::to_string(constant) +
         "</constant><linear>" + std::to_string(linear) + "</linear><quadratic>" +
         std::to_string(quadratic) + "</quadratic></attenuation></light>";
}

ImageData render(const WorldSpec& world) {
  Simulation sim(world, SimConfig());
  sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
  CameraRenderer renderer(sim);
  ImageData image;
  renderer.render("burger", 0, &image);
  return image;
}

/// Grey 0.5 under the light factor `light`, as a byte.
int grey(double light) { return static_cast<int>(std::lround(std::min(1.0, 0.5 * light) * 255)); }

/// The light factor at the wall point that column `col` of the middle row sees: ambient 0.1
/// plus diffuse * cos * 1 / (c + l d + q d^2).
double lightAtColumn(int col, double diffuse, double c, double l, double q) {
  const double y = (320 - col) * (kFaceX - kCamera.x()) / kFocal;
  const double height = kFaceX - kLightX;
  const double d = std::hypot(height, y);
  return 0.1 + diffuse * (height / d) / (c + l * d + q * d * d);
}

TEST(CameraLights, PointLightLightsTheWallPerPixel) {
  // AutoRace's lamps: diffuse 0.5, attenuation 0.5 / 0.01 / 0.001.
  const ImageData image = render(wallWorld(pointLight(0.5, 0.5, 0.01, 0.001)));
  // Straight ahead: d = 0.475, cos = 1, 1 / (0.5 + 0.00475 + 0.000226) = 1.980294;
  // 0.5 (0.1 + 0.5 * 1.980294) = 0.545074 -> 139.
  EXPECT_EQ(pixel(image, 320, 240).r, 139);
  EXPECT_EQ(grey(lightAtColumn(320, 0.5, 0.5, 0.01, 0.001)), 139);
  // 66 columns left, y = 0.300: d = 0.56185, cos = 0.845421, attenuation 1.976543;
  // 0.5 (0.1 + 0.5 * 0.845421 * 1.976543) = 0.467753 -> 119.
  EXPECT_EQ(pixel(image, 254, 240).r, 119);
  for (int col : {100, 200, 280, 400, 600}) {
    EXPECT_NEAR(pixel(image, col, 240).r, grey(lightAtColumn(col, 0.5, 0.5, 0.01, 0.001)), 1)
        << "column " << col;
  }
  // Without the light the wall is the ambient's alone: 0.05 -> 13.
  EXPECT_EQ(pixel(render(wallWorld("")), 320, 240).r, 13);
}

TEST(CameraLights, ConstantAttenuationIsClampedToOneAsGazeboDoes) {
  // Gazebo hands OGRE min(constant, 1): 0.5 (0.1 + 0.4 / 1) = 0.25 -> 64, not the
  // 0.5 (0.1 + 0.4 / 3) = 0.117 -> 30 of the file's constant.
  const ImageData image = render(wallWorld(pointLight(0.4, 3, 0, 0)));
  EXPECT_EQ(pixel(image, 320, 240).r, 64);
}

}  // namespace
