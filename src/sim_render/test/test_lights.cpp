// Point and spot lights as OGRE's per-pixel lighting adds them, against pixels worked out
// by hand. The camera looks straight down from 3.2 m at the ground (z = 0): fx = fy = 320,
// so pixel (col, row) shows the ground point (x, y) = (0.01 (240 - row), 0.01 (320 - col)).
#include "../src/polygon_raster.h"
#include "render_test_util.h"
#include "sim_render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

using namespace sim_render;
using namespace sim_render::test;

namespace {

const Eigen::Vector4f kGrey(0.5f, 0.5f, 0.5f, 1.0f);

CameraModel squareCamera() {
  CameraModel camera;
  camera.horizontal_fov_rad = M_PI / 2;
  return camera;
}

/// The ground in grey, ambient 0.1, no sun: what is lit beyond 0.1 is the lights' work.
Scene groundScene() {
  Scene scene;
  scene.lighting().ambient = Eigen::Vector3f(0.1f, 0.1f, 0.1f);
  scene.lighting().diffuse = Eigen::Vector3f::Zero();
  scene.add(ShapeSpec::plane(0, 0, kGrey), Eigen::Isometry3d::Identity());
  return scene;
}

std::vector<std::uint8_t> fromAbove(const Scene& scene) {
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> image;
  renderer.render(scene, cameraAt(Eigen::Vector3d(0, 0, 3.2), 0.0, M_PI / 2), image);
  return image;
}

/// The pixel that shows ground point (x, y), x and y multiples of 0.01 m.
Rgb groundPixel(const std::vector<std::uint8_t>& image, double x, double y) {
  return pixel(image, 640, static_cast<int>(std::lround(320 - 100 * y)),
               static_cast<int>(std::lround(240 - 100 * x)));
}

LocalLight pointLightAbove(double range_m) {
  LocalLight light;
  light.kind = LocalLight::Kind::Point;
  light.position = Eigen::Vector3d(0, 0, 1);
  light.diffuse = Eigen::Vector3f(0.6f, 0.6f, 0.6f);
  light.range_m = range_m;
  light.constant = 0.5;
  light.linear = 0.2;
  light.quadratic = 0.1;
  return light;
}

/// Grey 0.5 times `light`, as a byte.
Rgb grey(double light) { return expectedRgb(0.5 * light, 0.5 * light, 0.5 * light); }

}  // namespace

TEST(Lights, PointLightAddsDiffuseTimesCosineTimesAttenuation) {
  Scene scene = groundScene();
  scene.lighting().lights.push_back(pointLightAbove(10));
  const std::vector<std::uint8_t> image = fromAbove(scene);
  // Under the light: d = 1, cos = 1, attenuation 1 / (0.5 + 0.2 + 0.1) = 1.25;
  // 0.5 (0.1 + 0.6 * 1.25) = 0.425 -> 108.
  EXPECT_EQ(groundPixel(image, 0, 0), grey(0.85));
  EXPECT_EQ(groundPixel(image, 0, 0)[0], 108);
  // At (1, 0): d = sqrt 2, cos = 1 / sqrt 2, attenuation 1 / (0.5 + 0.2 sqrt 2 + 0.1 * 2)
  // = 1.017457; 0.5 (0.1 + 0.6 * 0.707107 * 1.017457) = 0.265836 -> 68.
  EXPECT_EQ(groundPixel(image, 1, 0)[0], 68);
  EXPECT_EQ(groundPixel(image, 0, -1)[0], 68);  // the same distance the other way
  // At (1.2, 0.5): d = 1.640122, cos = 0.609711, attenuation 1 / (0.5 + 0.328024 + 0.269)
  // = 0.911557; 0.5 (0.1 + 0.6 * 0.609711 * 0.911557) = 0.216740 -> 55.
  EXPECT_EQ(groundPixel(image, 1.2, 0.5)[0], 55);
}

TEST(Lights, NothingBeyondTheRange) {
  Scene scene = groundScene();
  scene.lighting().lights.push_back(pointLightAbove(1.5));
  const std::vector<std::uint8_t> image = fromAbove(scene);
  // Range 1.5 m reaches the ground out to sqrt(1.5^2 - 1) = 1.118 m from below the light.
  EXPECT_EQ(groundPixel(image, 1, 0)[0], 68);     // d = 1.414: lit as above
  EXPECT_GT(groundPixel(image, 1.11, 0)[0], 13);  // d = 1.494
  EXPECT_EQ(groundPixel(image, 1.12, 0), grey(0.1));  // d = 1.501: ambient alone, 13
  EXPECT_EQ(groundPixel(image, 0, 1.5), grey(0.1));
}

TEST(Lights, LightBehindASurfaceDoesNotLightIt) {
  Scene scene = groundScene();
  LocalLight below = pointLightAbove(10);
  below.position.z() = -1;
  scene.lighting().lights.push_back(below);
  const std::vector<std::uint8_t> image = fromAbove(scene);
  EXPECT_EQ(groundPixel(image, 0, 0), grey(0.1));
  EXPECT_EQ(groundPixel(image, 1, 0), grey(0.1));
}

TEST(Lights, SpotLightConeAndFalloffAsOgre) {
  Scene scene = groundScene();
  LocalLight spot;
  spot.kind = LocalLight::Kind::Spot;
  spot.position = Eigen::Vector3d(0, 0, 1);
  spot.direction = Eigen::Vector3d(0, 0, -1);
  spot.diffuse = Eigen::Vector3f(0.8f, 0.8f, 0.8f);
  spot.constant = 1;  // no attenuation within the range
  // Full cone angles (OGRE halves them): the inner cone meets the ground 0.5 m from its
  // centre, the outer one 1 m.
  spot.spot_inner_rad = 2 * std::atan(0.5);
  spot.spot_outer_rad = 2 * std::atan(1.0);
  spot.spot_falloff = 2;
  scene.lighting().lights.push_back(spot);
  const std::vector<std::uint8_t> image = fromAbove(scene);
  // Inside the inner cone, r = 0.4: d = 1.077033, cos = 0.928477, spot 1;
  // 0.5 (0.1 + 0.8 * 0.928477) = 0.421391 -> 107.
  EXPECT_EQ(groundPixel(image, 0.4, 0)[0], 107);
  EXPECT_EQ(groundPixel(image, 0, 0.4)[0], 107);
  // Between the cones, r = 0.75: rho = cos = 0.8, (0.8 - cos 45deg) / (cos 26.565deg -
  // cos 45deg) = 0.092893 / 0.187320 = 0.495904, squared 0.245921;
  // 0.5 (0.1 + 0.8 * 0.8 * 0.245921) = 0.128695 -> 33.
  EXPECT_EQ(groundPixel(image, 0.75, 0)[0], 33);
  // r = 0.9: rho = 0.743294, e = 0.193183, e^2 = 0.037320;
  // 0.5 (0.1 + 0.8 * 0.743294 * 0.037320) = 0.061096 -> 16.
  EXPECT_EQ(groundPixel(image, 0, -0.9)[0], 16);
  // Outside the outer cone, r = 1.05: ambient alone.
  EXPECT_EQ(groundPixel(image, 1.05, 0), grey(0.1));
  EXPECT_EQ(groundPixel(image, -0.8, -0.8), grey(0.1));  // r = 1.13
}

TEST(Lights, TexturedSurfaceIsTheTexelTimesThePixelsLight) {
  Scene scene;
  scene.lighting().ambient = Eigen::Vector3f(0.1f, 0.1f, 0.1f);
  scene.lighting().diffuse = Eigen::Vector3f::Zero();
  ShapeSpec floor = ShapeSpec::plane(4, 4, Eigen::Vector4f(1, 1, 1, 1));
  floor.texture = std::make_shared<const Texture>(1, 1, std::vector<std::uint8_t>{200, 100, 50});
  scene.add(floor, Eigen::Isometry3d::Identity());
  scene.lighting().lights.push_back(pointLightAbove(10));
  const std::vector<std::uint8_t> image = fromAbove(scene);
  // Under the light the factor is 0.85 (above): 200 * 0.85 = 170, 100 * 0.85 = 85,
  // 50 * 0.85 = 42.5; at (1, 0) it is 0.531671: 106.3, 53.2, 26.6 (within a unit: the
  // factor is applied in 1/256 steps, as for unlit texels).
  const Rgb under = groundPixel(image, 0, 0), off = groundPixel(image, 1, 0);
  const double expected_under[3] = {170, 85, 42.5}, expected_off[3] = {106.3, 53.2, 26.6};
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_NEAR(under[channel], expected_under[channel], 1.0) << channel;
    EXPECT_NEAR(off[channel], expected_off[channel], 1.0) << channel;
  }
}

TEST(Lights, DirectionalLightsBesidesTheSunAddTheirLambertTerm) {
  Scene scene = groundScene();
  LocalLight lamp;
  lamp.kind = LocalLight::Kind::Directional;
  lamp.direction = Eigen::Vector3d(0, 1, -1);  // 45 degrees: cos = 0.707107
  lamp.diffuse = Eigen::Vector3f(0.4f, 0.4f, 0.4f);
  scene.lighting().lights.push_back(lamp);
  const std::vector<std::uint8_t> image = fromAbove(scene);
  // 0.5 (0.1 + 0.4 * 0.707107) = 0.191421 -> 49, everywhere.
  EXPECT_EQ(groundPixel(image, 0, 0)[0], 49);
  EXPECT_EQ(groundPixel(image, 1.5, -2)[0], 49);
}

TEST(Lights, UnusableLightsAreLeftOut) {
  Scene scene = groundScene();
  LocalLight bad = pointLightAbove(10);
  bad.position.x() = std::nan("");
  scene.lighting().lights.push_back(bad);
  LocalLight no_range = pointLightAbove(0);
  scene.lighting().lights.push_back(no_range);
  const std::vector<std::uint8_t> image = fromAbove(scene);
  EXPECT_EQ(groundPixel(image, 0, 0), grey(0.1));
}

TEST(Lights, FourPixelsAtATimeAndOneAtATimeGiveTheSameLitFrame) {
  Scene scene;
  scene.lighting().ambient = Eigen::Vector3f(0.1f, 0.1f, 0.1f);
  std::vector<std::uint8_t> texels;
  for (int i = 0; i < 16; ++i) texels.insert(texels.end(), {std::uint8_t(i * 16), 200, std::uint8_t(255 - i * 16)});
  ShapeSpec floor = ShapeSpec::plane(4, 4, Eigen::Vector4f(1, 1, 1, 1));
  floor.texture = std::make_shared<const Texture>(4, 4, texels);
  scene.add(floor, Eigen::Isometry3d::Identity());
  scene.add(ShapeSpec::box(0.3, 0.3, 0.3, kGrey), at(0.5, 0.3, 0.15));
  scene.lighting().lights.push_back(pointLightAbove(10));
  LocalLight spot = pointLightAbove(10);
  spot.kind = LocalLight::Kind::Spot;
  spot.position = Eigen::Vector3d(-0.5, 0.5, 1.5);
  spot.spot_inner_rad = 0.4;
  spot.spot_outer_rad = 1.2;
  spot.spot_falloff = 1.5;
  scene.lighting().lights.push_back(spot);
  detail::setFourPixelTexturing(true);
  const std::vector<std::uint8_t> four = fromAbove(scene);
  detail::setFourPixelTexturing(false);
  const std::vector<std::uint8_t> one = fromAbove(scene);
  detail::setFourPixelTexturing(true);
  EXPECT_TRUE(four == one);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
