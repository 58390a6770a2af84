// Textured surfaces: which texel each pixel shows, against texture coordinates worked out
// by hand from Gazebo Classic's mappings (unit_plane, unit_box) and pinhole projection.
#include <gtest/gtest.h>

#include "../src/polygon_raster.h"
#include "render_test_util.h"
#include "sim_render/renderer.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>

namespace sim_render {
namespace {

using test::Rgb;

const Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kWhite{255, 255, 255},
    kBlack{0, 0, 0};

/// An image of `width` x `height` texels, each given by `colour_of(x, y)`.
template <class ColourOf>
std::shared_ptr<const Texture> makeTexture(int width, int height, ColourOf colour_of) {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(static_cast<size_t>(width) * height * 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Rgb c = colour_of(x, y);
      for (int channel = 0; channel < 3; ++channel) {
        rgb.push_back(static_cast<std::uint8_t>(c[channel]));
      }
    }
  }
  return std::make_shared<const Texture>(width, height, std::move(rgb));
}

/// Top-left red, top-right green, bottom-left blue, bottom-right white.
std::shared_ptr<const Texture> quadrants() {
  return makeTexture(2, 2, [](int x, int y) { return y == 0 ? (x == 0 ? kRed : kGreen)
                                                             : (x == 0 ? kBlue : kWhite); });
}

/// Full ambient, no diffuse: a pixel is its texel exactly.
Scene unlitScene() {
  Scene scene;
  scene.lighting().ambient = {1, 1, 1};
  scene.lighting().diffuse = {0, 0, 0};
  scene.lighting().background = {0.5f, 0.5f, 0.5f};
  return scene;
}

CameraModel camera(int width = 320, int height = 240) {
  CameraModel c;
  c.width = width;
  c.height = height;
  c.horizontal_fov_rad = M_PI / 2;
  return c;
}

/// The pixel a world point projects to, for a camera at T_world_camera.
Eigen::Vector2i pixelOf(const CameraModel& c, const Eigen::Isometry3d& T_world_camera,
                        const Eigen::Vector3d& p_world) {
  Eigen::Vector2d uv;
  EXPECT_TRUE(c.project(T_world_camera.inverse() * p_world, &uv));
  return Eigen::Vector2i(static_cast<int>(std::floor(uv.x())), static_cast<int>(std::floor(uv.y())));
}

Rgb seen(const std::vector<std::uint8_t>& image, const CameraModel& c, const Eigen::Vector2i& px) {
  return test::pixel(image, c.width, px.x(), px.y());
}

}  // namespace

TEST(Textures, APlaneShowsItsImageAsAMapWithXRightAndYUp) {
  // Gazebo's unit_plane: u = 0..1 from -x to +x, v = 0 at +y. Seen from 2 m above, the
  // quadrant centres (+-0.5, +-0.5) of a 2 m plane show red (-x,+y), green (+x,+y),
  // blue (-x,-y), white (+x,-y).
  Scene scene = unlitScene();
  ShapeSpec plane = ShapeSpec::plane(2, 2, {1, 1, 1, 1});
  plane.texture = quadrants();
  scene.add(plane, Eigen::Isometry3d::Identity());
  const CameraModel c = camera();
  const Eigen::Isometry3d T = test::cameraAt({0, 0, 2}, 0.3, M_PI / 2);
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  renderer.render(scene, T, image);
  EXPECT_EQ(seen(image, c, pixelOf(c, T, {-0.5, 0.5, 0})), kRed);
  EXPECT_EQ(seen(image, c, pixelOf(c, T, {0.5, 0.5, 0})), kGreen);
  EXPECT_EQ(seen(image, c, pixelOf(c, T, {-0.5, -0.5, 0})), kBlue);
  EXPECT_EQ(seen(image, c, pixelOf(c, T, {0.5, -0.5, 0})), kWhite);
  EXPECT_EQ(seen(image, c, pixelOf(c, T, {1.3, 0, 0})), (Rgb{128, 128, 128}));  // off the plane
}

TEST(Textures, AFloorSeenObliquelyIsPerspectiveCorrect) {
  // A level camera 0.3 m above a 4 m long floor strip from x 0.5 to 4.5 painted with 8
  // stripes along x (black, white, ...: 0.5 m each). The stripe under the ray through a
  // row is fixed by where that ray meets the floor; a screen-affine interpolation of the
  // coordinates would put the far stripes rows away from it.
  Scene scene = unlitScene();
  ShapeSpec floor = ShapeSpec::plane(4, 0.5, {1, 1, 1, 1});
  floor.texture = makeTexture(8, 1, [](int x, int) { return x % 2 ? kWhite : kBlack; });
  scene.add(floor, test::at(2.5, 0, 0));
  const CameraModel c = camera(320, 240);
  const Eigen::Isometry3d T = test::cameraAt({0, 0, 0.3});
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  renderer.render(scene, T, image);
  // Pixel row r samples the ray through image coordinate r (the renderer's convention, as
  // in CameraModel::project): it meets the floor at X = 0.3 fy / (r - cy).
  int rows_checked = 0;
  for (int row = static_cast<int>(c.cy()) + 1; row < c.height; ++row) {
    const double x = 0.3 * c.fy() / (row - c.cy());
    if (x < 0.5 || x > 4.5) continue;
    const double stripe = (x - 0.5) / 0.5;
    const double footprint_m = x * x / (0.3 * c.fy());  // floor length one row covers
    const double to_edge_m = 0.5 * std::min(stripe - std::floor(stripe), std::ceil(stripe) - stripe);
    if (to_edge_m < footprint_m) continue;  // the row straddles an edge
    const int k = static_cast<int>(stripe);
    EXPECT_EQ(test::pixel(image, c.width, c.width / 2, row), k % 2 ? kWhite : kBlack)
        << "row " << row << " meets the floor at x " << x;
    ++rows_checked;
  }
  EXPECT_GE(rows_checked, 60);
}

TEST(Textures, EachBoxFaceShowsTheWholeImageUprightFromOutside) {
  // Gazebo's unit_box: seen from outside every side face shows the image upright and
  // unmirrored (red at its top left). A 1 m cube, the camera 2 m from a face, level.
  Scene scene = unlitScene();
  ShapeSpec box = ShapeSpec::box(1, 1, 1, {1, 1, 1, 1});
  box.texture = quadrants();
  scene.add(box, Eigen::Isometry3d::Identity());
  const CameraModel c = camera();
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  for (double yaw : {0.0, M_PI / 2, M_PI, -M_PI / 2}) {
    SCOPED_TRACE(yaw);
    // The camera 2.5 m from the centre, looking at it.
    const Eigen::Vector3d from(-2.5 * std::cos(yaw), -2.5 * std::sin(yaw), 0);
    const Eigen::Isometry3d T = test::cameraAt(from, yaw);
    renderer.render(scene, T, image);
    // Camera-left is +90 degrees from the viewing direction.
    const Eigen::Vector3d left(-std::sin(yaw), std::cos(yaw), 0), up(0, 0, 1);
    const Eigen::Vector3d face_centre = from * 0.5 / 2.5;
    EXPECT_EQ(seen(image, c, pixelOf(c, T, face_centre + 0.25 * left + 0.25 * up)), kRed);
    EXPECT_EQ(seen(image, c, pixelOf(c, T, face_centre - 0.25 * left + 0.25 * up)), kGreen);
    EXPECT_EQ(seen(image, c, pixelOf(c, T, face_centre + 0.25 * left - 0.25 * up)), kBlue);
    EXPECT_EQ(seen(image, c, pixelOf(c, T, face_centre - 0.25 * left - 0.25 * up)), kWhite);
  }
}

TEST(Textures, AMeshUsesItsOwnCoordinatesThroughTheUvTransform) {
  // A 1 m square facing -x whose corners carry coordinates that show only the image's
  // right half; the transform (OGRE scale 0.5 about the centre) then doubles that.
  auto quad = std::make_shared<Mesh>();
  quad->vertices = {{0, 0.5, -0.5}, {0, -0.5, -0.5}, {0, -0.5, 0.5}, {0, 0.5, 0.5}};
  quad->triangles = {{0, 1, 2}, {0, 2, 3}};
  quad->uvs = {{0.5f, 1}, {1, 1}, {1, 0}, {0.5f, 0}};
  const CameraModel c = camera();
  const Eigen::Isometry3d T = test::cameraAt({-2, 0, 0});
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  {
    Scene scene = unlitScene();
    ShapeSpec mesh = ShapeSpec::mesh(quad, {1, 1, 1}, {1, 1, 1, 1});
    mesh.texture = quadrants();
    scene.add(mesh, Eigen::Isometry3d::Identity());
    renderer.render(scene, T, image);
    EXPECT_EQ(seen(image, c, pixelOf(c, T, {0, 0.25, 0.25})), kGreen);   // left half: right column
    EXPECT_EQ(seen(image, c, pixelOf(c, T, {0, -0.25, -0.25})), kWhite);
  }
  {
    Scene scene = unlitScene();
    ShapeSpec mesh = ShapeSpec::mesh(quad, {1, 1, 1}, {1, 1, 1, 1});
    mesh.texture = quadrants();
    mesh.uv_transform.scale = {2, 1};     // u' = 2 u - 0.5 (OGRE `scale 0.5 1`)
    mesh.uv_transform.offset = {-0.5f, 0};
    scene.add(mesh, Eigen::Isometry3d::Identity());
    renderer.render(scene, T, image);
    // u' runs 0.5 .. 1.5: green at the left edge, then red past the wrap at u' = 1.
    EXPECT_EQ(seen(image, c, pixelOf(c, T, {0, 0.4, 0.25})), kGreen);
    EXPECT_EQ(seen(image, c, pixelOf(c, T, {0, -0.4, 0.25})), kRed);
  }
}

TEST(Textures, LightingScalesTheTexelAndAColourTintsIt) {
  // Ambient 0.5 and a half-grey tint: a white texel becomes 255 * 0.5 * 0.5 = 64.
  Scene scene = unlitScene();
  scene.lighting().ambient = {0.5f, 0.5f, 0.5f};
  ShapeSpec box = ShapeSpec::box(1, 1, 1, {0.5f, 1, 1, 1});
  box.texture = makeTexture(1, 1, [](int, int) { return kWhite; });
  scene.add(box, Eigen::Isometry3d::Identity());
  const CameraModel c = camera();
  const Eigen::Isometry3d T = test::cameraAt({-2.5, 0, 0});
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  renderer.render(scene, T, image);
  EXPECT_EQ(seen(image, c, pixelOf(c, T, {-0.5, 0, 0})), (Rgb{64, 128, 128}));
}

TEST(Textures, FarAwayAFineTextureShowsItsMeanNotAliasing) {
  // A 1-texel checkerboard of black and white (64 x 64 texels on a 2 m plane) seen from
  // 60 m: each pixel covers many texels, so the mipmap gives grey (127 or 128), where
  // nearest sampling of level 0 would give black or white.
  Scene scene = unlitScene();
  ShapeSpec plane = ShapeSpec::plane(2, 2, {1, 1, 1, 1});
  plane.texture = makeTexture(64, 64, [](int x, int y) { return (x + y) % 2 ? kWhite : kBlack; });
  scene.add(plane, Eigen::Isometry3d::Identity());
  const CameraModel c = camera();
  const Eigen::Isometry3d T = test::cameraAt({0, 0, 60}, 0, M_PI / 2);
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  renderer.render(scene, T, image);
  const Rgb centre = seen(image, c, pixelOf(c, T, {0, 0, 0}));
  EXPECT_NEAR(centre[0], 127.5, 1.0);
}

TEST(Textures, WithoutCoordinatesATexturedShapeShowsTheMeanColour) {
  // A cylinder has no texture coordinates here: red and blue halves give (127.5, 0, 127.5).
  Scene scene = unlitScene();
  ShapeSpec cylinder = ShapeSpec::cylinder(0.5, 1, {1, 1, 1, 1});
  cylinder.texture = makeTexture(2, 1, [](int x, int) { return x ? kBlue : kRed; });
  scene.add(cylinder, Eigen::Isometry3d::Identity());
  const CameraModel c = camera();
  const Eigen::Isometry3d T = test::cameraAt({-2.5, 0, 0});
  Renderer renderer(c);
  std::vector<std::uint8_t> image;
  renderer.render(scene, T, image);
  const Rgb centre = seen(image, c, pixelOf(c, T, {-0.5, 0, 0}));
  EXPECT_NEAR(centre[0], 128, 1);
  EXPECT_EQ(centre[1], 0);
  EXPECT_NEAR(centre[2], 128, 1);
}

TEST(Textures, BadTextureSizesAreNamed) {
  try {
    Texture(0, 4, {});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "texture size must be positive, got 0 x 4");
  }
  try {
    Texture(2, 2, std::vector<std::uint8_t>(5));
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "texture of 2 x 2 needs 12 bytes of rgb8, got 5");
  }
}

#if defined(__SSE2__)
TEST(Textures, FourAtATimeFloorIsStdFloorToTheBit) {
  const float big = 8388608.0f;  // 2^23: from here on every float is whole
  const float values[] = {0.0f, -0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 0.999999f, -0.999999f,
                          1e-30f, -1e-30f, 1e-42f, -1e-42f, 2.5f, -2.5f, 49.75f, -49.75f,
                          big - 0.5f, -(big - 0.5f), big, -big, big + 1.0f, 3e9f, -3e9f,
                          1e30f, -1e30f, std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN()};
  constexpr size_t kCount = sizeof(values) / sizeof(values[0]);
  for (size_t i = 0; i + 4 <= kCount; i += 4) {
    float out[4];
    detail::floorFour(values + i, out);
    for (size_t lane = 0; lane < 4; ++lane) {
      const float expected = std::floor(values[i + lane]);
      std::uint32_t got_bits, expected_bits;
      std::memcpy(&got_bits, &out[lane], 4);
      std::memcpy(&expected_bits, &expected, 4);
      EXPECT_EQ(got_bits, expected_bits) << "floor of " << values[i + lane];
    }
  }
}
#endif

TEST(Textures, FourPixelsAtATimeAndOneAtATimeGiveTheSameFrame) {
  // A lit scene (texels scaled by the light) of a floor tiled 40 times each way, seen at a
  // grazing angle so that its far rows take small mipmap levels and its coordinates run
  // from -20 to 20, and a tilted box: every pixel the same either way.
  Scene scene;
  scene.lighting().ambient = {0.3f, 0.3f, 0.3f};
  scene.lighting().diffuse = {0.8f, 0.7f, 0.6f};
  scene.lighting().direction = {0.3, -0.4, -1.0};
  ShapeSpec floor = ShapeSpec::plane(20, 20, {1, 1, 1, 1});
  floor.texture = makeTexture(64, 48, [](int x, int y) {
    return Rgb{(x * 37 + y * 11) % 256, (x * 5 + y * 53) % 256, (x * y) % 256};
  });
  floor.uv_transform.scale = {40.0f, 40.0f};
  floor.uv_transform.offset = {-19.5f, -19.5f};
  scene.add(floor, Eigen::Isometry3d::Identity());
  ShapeSpec box = ShapeSpec::box(0.6, 0.8, 0.5, {0.9f, 0.8f, 0.7f, 1});
  box.texture = quadrants();
  scene.add(box, test::at(1.5, 0.4, 0.25) * Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()));
  const CameraModel c = camera(333, 217);  // rows not a multiple of four pixels long
  Renderer renderer(c);
  std::vector<std::uint8_t> four, one;
  for (const double yaw : {0.0, 0.4, -1.1, 2.7}) {
    SCOPED_TRACE(yaw);
    const Eigen::Isometry3d T = test::cameraAt({-0.5, 0.2, 0.35}, yaw, 0.15);
    detail::setFourPixelTexturing(true);
    renderer.render(scene, T, four);
    detail::setFourPixelTexturing(false);
    renderer.render(scene, T, one);
    detail::setFourPixelTexturing(true);
    EXPECT_EQ(four, one);
    EXPECT_NE(four, std::vector<std::uint8_t>(four.size(), four[0]));  // something drawn
  }
}

}  // namespace sim_render

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
