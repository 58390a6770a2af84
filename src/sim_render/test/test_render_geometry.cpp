// Renders simple scenes and checks them against geometry projected by hand through K.
#include "render_test_util.h"
#include "sim_render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace sim_render;
using namespace sim_render::test;

namespace {

// 640 x 480, hfov 90 degrees: fx = fy = 320, cx = 320, cy = 240.
CameraModel squareCamera(double far_m = 100.0) {
  CameraModel camera;
  camera.horizontal_fov_rad = M_PI / 2;
  camera.clip_far_m = far_m;
  return camera;
}

// Flat light so that every face shows exactly its colour.
void flatLight(Scene& scene) {
  scene.lighting().ambient = Eigen::Vector3f(1, 1, 1);
  scene.lighting().diffuse = Eigen::Vector3f(0, 0, 0);
  scene.lighting().background = Eigen::Vector3f(0, 0, 0);
}

const Eigen::Vector4f kRed(1, 0, 0, 1), kBlue(0, 0, 1, 1), kGreen(0, 1, 0, 1);

/// The square camera after a frame of the endless green ground from `height_m` above it.
std::unique_ptr<Renderer> groundFrom(double height_m) {
  Scene scene;
  scene.add(ShapeSpec::plane(0, 0, kGreen), Eigen::Isometry3d::Identity());
  auto renderer = std::make_unique<Renderer>(squareCamera(100.0));
  std::vector<std::uint8_t> image;
  renderer->render(scene, cameraAt(Eigen::Vector3d(0, 0, height_m)), image);
  return renderer;
}

}  // namespace

TEST(Render, BoxCoversItsProjectedRectangle) {
  Scene scene;
  flatLight(scene);
  const Eigen::Vector3d size(0.2, 1.0, 0.6), centre(3.0, 0.3, -0.1);
  scene.add(ShapeSpec::box(size.x(), size.y(), size.z(), kRed), at(centre.x(), centre.y(), centre.z()));
  const CameraModel camera = squareCamera();
  Renderer renderer(camera);
  std::vector<std::uint8_t> image;
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  ASSERT_EQ(image.size(), 640u * 480u * 3u);

  // Bounding rectangle of the eight projected corners.
  double u_min = 1e9, u_max = -1e9, v_min = 1e9, v_max = -1e9;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner = centre + 0.5 * Eigen::Vector3d((i & 1) ? size.x() : -size.x(),
                                                                  (i & 2) ? size.y() : -size.y(),
                                                                  (i & 4) ? size.z() : -size.z());
    Eigen::Vector2d uv;
    ASSERT_TRUE(camera.project(corner, &uv));
    u_min = std::min(u_min, uv.x());
    u_max = std::max(u_max, uv.x());
    v_min = std::min(v_min, uv.y());
    v_max = std::max(v_max, uv.y());
  }
  int col_min = 640, col_max = -1, row_min = 480, row_max = -1;
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const Rgb p = pixel(image, 640, col, row);
      if (p == Rgb{0, 0, 0}) continue;
      EXPECT_EQ(p, (Rgb{255, 0, 0})) << "col " << col << " row " << row;
      col_min = std::min(col_min, col);
      col_max = std::max(col_max, col);
      row_min = std::min(row_min, row);
      row_max = std::max(row_max, row);
    }
  }
  EXPECT_NEAR(col_min, u_min, 1.0);
  EXPECT_NEAR(col_max, u_max, 1.0);
  EXPECT_NEAR(row_min, v_min, 1.0);
  EXPECT_NEAR(row_max, v_max, 1.0);
  // Filled without holes: every pixel strictly inside the rectangle is red.
  for (int row = static_cast<int>(std::ceil(v_min)); row < v_max; ++row) {
    for (int col = static_cast<int>(std::ceil(u_min)); col < u_max; ++col) {
      ASSERT_EQ(pixel(image, 640, col, row), (Rgb{255, 0, 0})) << "hole at col " << col << " row " << row;
    }
  }
  // The front face is at x = 2.9.
  EXPECT_NEAR(renderer.depthAt(320, 240), 2.9, 1e-4);
}

TEST(Render, MeshBoxDrawsExactlyLikeThePrimitiveBox) {
  // The primitive's own triangles handed back as a mesh, scaled from a unit box, and turned.
  const std::shared_ptr<const Mesh> unit =
      std::make_shared<Mesh>(tessellate(ShapeSpec::box(1, 1, 1, kRed)));
  Eigen::Isometry3d pose = at(2.5, -0.2, 0.1);
  pose.rotate(Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.2, 0.3, 1).normalized()));
  Scene primitive, mesh;
  primitive.add(ShapeSpec::box(0.3, 0.8, 0.5, kRed), pose);
  mesh.add(ShapeSpec::mesh(unit, Eigen::Vector3d(0.3, 0.8, 0.5), kRed), pose);
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> a, b;
  renderer.render(primitive, Eigen::Isometry3d::Identity(), a);
  renderer.render(mesh, Eigen::Isometry3d::Identity(), b);
  EXPECT_EQ(a, b);
  EXPECT_GT(renderer.lastStats().triangles_drawn, 0u);
}

TEST(Render, HorizonOfTheGroundIsAtCyForALevelCamera) {
  for (double plane_size : {0.0, 5000.0}) {  // infinite and large finite
    Scene scene;
    flatLight(scene);
    scene.add(ShapeSpec::plane(plane_size, plane_size, kGreen), Eigen::Isometry3d::Identity());
    Renderer renderer(squareCamera(1e4));
    std::vector<std::uint8_t> image;
    renderer.render(scene, cameraAt(Eigen::Vector3d(0.3, -0.2, 0.3), 0.7), image);
    for (int col : {0, 160, 320, 479, 639}) {
      int first_ground_row = -1;
      for (int row = 0; row < 480 && first_ground_row < 0; ++row) {
        if (pixel(image, 640, col, row) == Rgb{0, 255, 0}) first_ground_row = row;
      }
      EXPECT_NEAR(first_ground_row, 240.0, 1.0) << "plane size " << plane_size << " col " << col;
    }
  }
}

TEST(Render, GroundDepthIsPerspectiveCorrectAndFarClipped) {
  Scene scene;
  flatLight(scene);
  scene.add(ShapeSpec::plane(0, 0, kGreen), Eigen::Isometry3d::Identity());
  const double height_m = 0.3;
  Renderer renderer(squareCamera(100.0));
  std::vector<std::uint8_t> image;
  renderer.render(scene, cameraAt(Eigen::Vector3d(0, 0, height_m)), image);
  // Row v sees the ground at depth h * fy / (v - cy).
  for (int row : {250, 300, 400, 479}) {
    const double expected = height_m * 320.0 / (row - 240.0);
    EXPECT_NEAR(renderer.depthAt(320, row), expected, 1e-4 * expected) << "row " << row;
  }
  // Beyond 100 m the ground is clipped: rows with v - cy < h * fy / 100 = 0.96 show the sky.
  EXPECT_EQ(pixel(image, 640, 320, 240), (Rgb{0, 0, 0}));
  EXPECT_EQ(pixel(image, 640, 320, 241), (Rgb{0, 255, 0}));
}

TEST(Render, DepthImageIsTheGroundsDepthPerRowAndNaNWhereTheSkyIs) {
  const double height_m = 0.3;
  std::vector<float> depth;
  groundFrom(height_m)->depthImage(&depth);
  ASSERT_EQ(depth.size(), 640u * 480u);
  for (int row : {0, 120, 240}) EXPECT_TRUE(std::isnan(depth[row * 640 + 17])) << "row " << row;
  // Row v sees the ground at depth h * fy / (v - cy), the same in every column.
  for (int row : {241, 300, 479}) {
    const double expected = height_m * 320.0 / (row - 240.0);
    for (int col : {0, 320, 639}) {
      EXPECT_NEAR(depth[row * 640 + col], expected, 1e-4 * expected) << col << ", " << row;
    }
  }
}

TEST(Render, DepthImageKeepsOnlyDepthsStrictlyBetweenTheCutoffs) {
  const double height_m = 0.3;
  std::vector<float> depth;
  groundFrom(height_m)->depthImage(&depth, 0.5f, 1.0f);
  ASSERT_EQ(depth.size(), 640u * 480u);
  // Row v sees the ground at h * fy / (v - cy): 1.0 m at row 336, 0.5 m at row 432.
  int kept = 0;
  for (int row = 241; row < 480; ++row) {
    const double expected = height_m * 320.0 / (row - 240.0);
    const float got = depth[row * 640 + 100];
    if (expected > 0.5 * (1 + 1e-3) && expected < 1.0 * (1 - 1e-3)) {
      EXPECT_NEAR(got, expected, 1e-4 * expected) << "row " << row;
      ++kept;
    } else if (expected < 0.5 * (1 - 1e-3) || expected > 1.0 * (1 + 1e-3)) {
      EXPECT_TRUE(std::isnan(got)) << "row " << row << " reads " << got;
    }
  }
  EXPECT_EQ(kept, 431 - 337 + 1);  // rows 337 to 431
  for (int row : {0, 120, 240}) EXPECT_TRUE(std::isnan(depth[row * 640 + 17])) << "row " << row;
}

TEST(Render, WallFacingTheLightShowsColourTimesAmbientPlusDiffuse) {
  Scene scene;
  scene.lighting().ambient = Eigen::Vector3f(0.3f, 0.3f, 0.3f);
  scene.lighting().diffuse = Eigen::Vector3f(0.5f, 0.5f, 0.5f);
  scene.lighting().direction = Eigen::Vector3d(2, 0, 0);  // travels +x: lights faces looking -x
  const Eigen::Vector4f colour(0.5f, 0.3f, 0.2f, 1);
  scene.add(ShapeSpec::box(0.015, 2, 1, colour), at(2, 0, 0));
  // A second wall seen edge-on to the light (its face looks along -y): ambient only.
  Eigen::Isometry3d side = at(1.5, 1.0, 0);
  side.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  scene.add(ShapeSpec::box(0.015, 0.4, 1, colour), side);
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> image;
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  EXPECT_EQ(pixel(image, 640, 320, 240), expectedRgb(0.5 * 0.8, 0.3 * 0.8, 0.2 * 0.8));
  // The side wall's face at y = 0.9925 spans x 1.3..1.7: u = 320 - 320 y / x, about 76..133.
  EXPECT_EQ(pixel(image, 640, 100, 240), expectedRgb(0.5 * 0.3, 0.3 * 0.3, 0.2 * 0.3));
  // Brighter than 1 saturates.
  scene.lighting().ambient = Eigen::Vector3f(0.4f, 0.4f, 0.4f);
  scene.lighting().diffuse = Eigen::Vector3f(0.8f, 0.8f, 0.8f);
  scene.setColor(1, Eigen::Vector4f(0.57f, 0.9f, 0.25f, 1));
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  EXPECT_EQ(pixel(image, 640, 320, 240), expectedRgb(0.57 * 1.2, 1.0, 0.25 * 1.2));
}

TEST(Render, NearerShapesOccludeFartherOnesInAnyOrder) {
  for (bool near_first : {true, false}) {
    Scene scene;
    flatLight(scene);
    if (near_first) scene.add(ShapeSpec::box(0.2, 0.5, 0.5, kRed), at(2, 0, 0));
    scene.add(ShapeSpec::box(0.2, 3, 3, kBlue), at(4, 0, 0));
    if (!near_first) scene.add(ShapeSpec::box(0.2, 0.5, 0.5, kRed), at(2, 0, 0));
    Renderer renderer(squareCamera());
    std::vector<std::uint8_t> image;
    renderer.render(scene, Eigen::Isometry3d::Identity(), image);
    // Red face at x = 1.9 covers |u - 320| < 320 * 0.25 / 1.9 = 42 px.
    EXPECT_EQ(pixel(image, 640, 320, 240), (Rgb{255, 0, 0})) << "near_first " << near_first;
    EXPECT_EQ(pixel(image, 640, 355, 205), (Rgb{255, 0, 0})) << "near_first " << near_first;
    EXPECT_EQ(pixel(image, 640, 370, 240), (Rgb{0, 0, 255})) << "near_first " << near_first;
    EXPECT_NEAR(renderer.depthAt(320, 240), 1.9, 1e-4);
    EXPECT_NEAR(renderer.depthAt(370, 240), 3.9, 1e-3);
  }
}

TEST(Render, PlanePassingUnderTheCameraIsClippedWithoutArtifacts) {
  for (double pitch_down : {0.0, 0.5}) {
    Scene scene;
    flatLight(scene);
    scene.add(ShapeSpec::plane(200, 200, kGreen), Eigen::Isometry3d::Identity());
    Renderer renderer(squareCamera(1e4));
    std::vector<std::uint8_t> image;
    renderer.render(scene, cameraAt(Eigen::Vector3d(1, 2, 0.3), 0.3, pitch_down), image);
    EXPECT_GT(renderer.lastStats().triangles_clipped, 0u);
    // The horizon of a camera pitched down by p is at v = cy - fy tan(p). The 200 m plane
    // ends at about 100 m, a fraction of a pixel below that.
    const double horizon = 240.0 - 320.0 * std::tan(pitch_down);
    int wrong = 0;
    for (int row = 0; row < 480; ++row) {
      if (std::abs(row - horizon) <= 2.0) continue;
      const Rgb expected = row > horizon ? Rgb{0, 255, 0} : Rgb{0, 0, 0};
      for (int col = 0; col < 640; ++col) wrong += pixel(image, 640, col, row) != expected;
    }
    EXPECT_EQ(wrong, 0) << "pitch " << pitch_down;
  }
}

TEST(Render, TessellatedSphereHasNoCracks) {
  Scene scene;
  flatLight(scene);
  const double radius = 1.0, distance = 3.0;
  scene.add(ShapeSpec::sphere(radius, kRed), at(distance, 0.1, -0.2));
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> image;
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  // The default 12 x 24 polyhedron holds the sphere of radius r cos(pi / 12) cos(pi / 24):
  // every ray that meets that sphere must hit a triangle.
  const double inner = radius * std::cos(M_PI / 12) * std::cos(M_PI / 24);
  const Eigen::Vector3d centre(distance, 0.1, -0.2);
  int checked = 0;
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) {
      const Eigen::Vector3d ray = Eigen::Vector3d(1, -(col - 320) / 320.0, -(row - 240) / 320.0).normalized();
      const double miss_distance = (centre - centre.dot(ray) * ray).norm();
      if (miss_distance >= inner) continue;
      ++checked;
      ASSERT_EQ(pixel(image, 640, col, row), (Rgb{255, 0, 0})) << "crack at col " << col << " row " << row;
    }
  }
  EXPECT_GT(checked, 30000);
}

TEST(Render, SameSceneGivesSameBytes) {
  Scene scene;
  scene.add(ShapeSpec::plane(0, 0, kGreen), Eigen::Isometry3d::Identity());
  scene.add(ShapeSpec::sphere(0.5, kRed), at(3, 0.2, 0.4));
  scene.add(ShapeSpec::cylinder(0.2, 1.0, kBlue), at(2.5, -0.8, 0.5));
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> first, second;
  renderer.render(scene, cameraAt(Eigen::Vector3d(0, 0, 0.5), 0.05, 0.1), first);
  renderer.render(scene, cameraAt(Eigen::Vector3d(0, 0, 0.5), 0.05, 0.1), second);
  EXPECT_EQ(first, second);
  Renderer other(squareCamera());
  other.render(scene, cameraAt(Eigen::Vector3d(0, 0, 0.5), 0.05, 0.1), second);
  EXPECT_EQ(first, second);
}

TEST(Render, ShapeBehindTheCameraOrInsideItIsNotDrawn) {
  Scene scene;
  flatLight(scene);
  scene.add(ShapeSpec::box(1, 1, 1, kRed), at(-3, 0, 0));
  scene.add(ShapeSpec::box(0.05, 0.05, 0.05, kBlue), Eigen::Isometry3d::Identity());  // camera housing
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> image;
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  EXPECT_TRUE(std::all_of(image.begin(), image.end(), [](std::uint8_t b) { return b == 0; }));
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

TEST(Render, EveryPixelNothingCoversIsTheBackground) {
  Scene scene;
  flatLight(scene);
  scene.lighting().background = Eigen::Vector3f(0.2f, 0.6f, 1.0f);  // bytes 51, 153, 255
  scene.add(ShapeSpec::box(1, 1, 1, kRed), at(3, 0, 0));
  CameraModel camera = squareCamera();
  camera.width = 37;  // odd sizes: no row length or count is a multiple of anything
  camera.height = 23;
  Renderer renderer(camera);
  std::vector<std::uint8_t> image;
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  // Then the box out of view: the same buffer again, now all background.
  renderer.render(scene, at(0, 0, 10), image);
  ASSERT_EQ(image.size(), 37u * 23u * 3u);
  int background = 0;
  for (int row = 0; row < 23; ++row) {
    for (int col = 0; col < 37; ++col) {
      background += pixel(image, 37, col, row) == (Rgb{51, 153, 255});
    }
  }
  EXPECT_EQ(background, 37 * 23);
}

TEST(Render, ShapesWithPosesThatAreNotFiniteAreLeftOutAndTheOthersDrawnInDepthOrder) {
  Scene scene;
  flatLight(scene);
  // 40 small boxes in a row along the optical axis (more than a sort handles by insertion),
  // every third one with a NaN or infinite position, as after a simulation blew up.
  for (int k = 0; k < 40; ++k) {
    Eigen::Isometry3d pose = at(2.0 + 0.5 * k, 0, 0);
    if (k % 3 == 1) pose.translation().x() = k % 2 ? std::nan("") : INFINITY;
    scene.add(ShapeSpec::box(0.1, 0.1, 0.1, k == 0 ? kRed : kBlue), pose);
  }
  Renderer renderer(squareCamera());
  std::vector<std::uint8_t> image;
  renderer.render(scene, Eigen::Isometry3d::Identity(), image);
  EXPECT_EQ(renderer.lastStats().shapes_drawn, 40u - 13u);
  // The nearest box (red, 2 m ahead: its front face at 1.95 m) covers the centre pixel.
  EXPECT_EQ(pixel(image, 640, 320, 240), (Rgb{255, 0, 0}));
  EXPECT_NEAR(renderer.depthAt(320, 240), 1.95, 1e-4);
}
