// The wide-angle camera against the lens function worked by hand: coloured boxes 3 m from
// wide_angle_robot.urdf's camera at known angles from its optical axis appear at image
// radius r = c1 * f * fun(theta / c2) half widths from the centre, along their azimuth;
// beyond the cutoff angle the image is black; the equidistant lens puts r in proportion
// to theta; only the cube faces the lens sees are rendered.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "bullet_sim/errors.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/simulation.h"
#include "render/lens_camera.h"
#include "wide_angle_fixture.h"

namespace {

using bullet_sim::ImageData;
using bullet_sim::Pose3;
using bullet_sim::StaticShape;
using bullet_sim_test::wideAngleFixtureWith;
using Eigen::Vector3d;

constexpr int kWidth = 320, kHeight = 240;
constexpr double kHalfWidth = kWidth / 2.0;
constexpr double kDeg = M_PI / 180;
constexpr double kDistance = 3.0;
const Vector3d kCamera(0, 0, 0.5);  // the base at the origin, camera_link 0.5 m above

/// A box seen at `azimuth` (left of the axis, positive) and `elevation` from the camera,
/// turned to face it, in a flat colour.
struct Target {
  double azimuth, elevation;
  Eigen::Vector4f rgba;
};
const Eigen::Vector4f kRed(1, 0, 0, 1), kGreen(0, 1, 0, 1), kBlue(0, 0, 1, 1),
    kYellow(1, 1, 0, 1);

StaticShape boxAt(const Target& t, int index) {
  StaticShape s;
  s.kind = StaticShape::Box;
  s.model = s.link = "box" + std::to_string(index);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(t.azimuth, Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(-t.elevation, Vector3d::UnitY()))
                                .matrix();
  s.pose.position = kCamera + kDistance * R * Vector3d::UnitX();
  s.pose.orientation = Eigen::Quaterniond(R);
  s.size = Vector3d(0.2, 0.2, 0.2);
  s.rgba = t.rgba;
  return s;
}

struct Frame {
  ImageData image;
  bullet_sim::CameraInfoData info;
};

/// Renders the fixture (with `replacements`) among `targets`; full ambient light, so that
/// every face shows its colour unshaded.
Frame render(const std::string& urdf, const std::vector<Target>& targets) {
  bullet_sim::WorldSpec world;
  world.ambient = Eigen::Vector4f::Ones();
  for (size_t i = 0; i < targets.size(); ++i) world.shapes.push_back(boxAt(targets[i], i));
  bullet_sim::Simulation sim(world, bullet_sim::SimConfig{});
  sim.spawnRobot("wide_bot", bullet_sim::parseRobot(urdf, "wide_angle_robot.urdf"), Pose3{});
  bullet_sim::CameraRenderer renderer(sim);
  Frame frame;
  renderer.render("wide_bot", 0, &frame.image);
  frame.info = bullet_sim::cameraInfo(sim.robotSpec("wide_bot").cameras.at(0), 0);
  return frame;
}

const uint8_t* pixel(const ImageData& image, int col, int row) {
  return &image.data[static_cast<size_t>(row) * image.step + 3 * static_cast<size_t>(col)];
}

bool hasColour(const uint8_t* p, const Eigen::Vector4f& rgba) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(p[c] - 255.0 * rgba[c]) > 1) return false;
  }
  return true;
}

bool isBlack(const uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 0; }

/// Centroid (pixel centres at +0.5) of the pixels of colour `rgba`, and their count.
struct Blob {
  double col = 0, row = 0;
  int pixels = 0;
};
Blob blobOf(const ImageData& image, const Eigen::Vector4f& rgba) {
  Blob blob;
  for (int row = 0; row < image.height; ++row) {
    for (int col = 0; col < image.width; ++col) {
      if (!hasColour(pixel(image, col, row), rgba)) continue;
      blob.col += col + 0.5;
      blob.row += row + 0.5;
      ++blob.pixels;
    }
  }
  if (blob.pixels > 0) blob.col /= blob.pixels, blob.row /= blob.pixels;
  return blob;
}

/// The fixture's lens, by hand: c1 = 1.05, c2 = 4, tan, f scaled so that r(hfov / 2) = 1:
/// r(theta) = c1 f tan(theta / 4) = tan(theta / 4) / tan(hfov / 8).
double customRadius(double theta, double hfov) { return std::tan(theta / 4) / std::tan(hfov / 8); }

void expectBlobAt(const ImageData& image, const Eigen::Vector4f& rgba, double col, double row,
                  const std::string& what) {
  const Blob blob = blobOf(image, rgba);
  ASSERT_GT(blob.pixels, 20) << what << " is not in the image";
  EXPECT_NEAR(blob.col, col, 1.5) << what;
  EXPECT_NEAR(blob.row, row, 1.5) << what;
}

TEST(WideAngleCamera, BoxesLandWhereTheLensFunctionPutsThem) {
  const double hfov = 4.0;
  const Frame frame = render(wideAngleFixtureWith(), {{0, 0, kRed},
                                                      {80 * kDeg, 0, kGreen},
                                                      {-100 * kDeg, 0, kBlue},
                                                      {0, 30 * kDeg, kYellow}});
  ASSERT_EQ(frame.image.width, kWidth);
  ASSERT_EQ(frame.image.height, kHeight);
  const double cx = kHalfWidth, cy = kHeight / 2.0;
  expectBlobAt(frame.image, kRed, cx, cy, "the box straight ahead");
  // 80 degrees left: r = tan(20 deg) / tan(0.5) = 0.666, column 160 - 106.6 = 53.4.
  expectBlobAt(frame.image, kGreen, cx - kHalfWidth * customRadius(80 * kDeg, hfov), cy,
               "the box 80 degrees left");
  // 100 degrees right, behind the camera's plane: r = 0.854, column 296.6.
  expectBlobAt(frame.image, kBlue, cx + kHalfWidth * customRadius(100 * kDeg, hfov), cy,
               "the box 100 degrees right");
  // 30 degrees up: r = 0.241, row 120 - 38.6 = 81.4.
  expectBlobAt(frame.image, kYellow, cx, cy - kHalfWidth * customRadius(30 * kDeg, hfov),
               "the box 30 degrees up");
}

TEST(WideAngleCamera, PixelsBeyondTheCutoffAngleAreBlack) {
  const double hfov = 4.0, cutoff = 1.2;
  const Frame frame = render(
      wideAngleFixtureWith({{"<cutoff_angle>3.1415<", "<cutoff_angle>1.2<"}}),
      {{0, 0, kRed}, {80 * kDeg, 0, kGreen}, {-100 * kDeg, 0, kBlue}});
  const double cut_radius_px = kHalfWidth * customRadius(cutoff, hfov);  // 90.6 px
  int black_inside = 0, lit_outside = 0;
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const double r_px = std::hypot(col + 0.5 - kHalfWidth, row + 0.5 - kHeight / 2.0);
      if (std::abs(r_px - cut_radius_px) < 1.0) continue;  // the rim's pixels may go either way
      const bool black = isBlack(pixel(frame.image, col, row));
      if (r_px < cut_radius_px && black) ++black_inside;
      if (r_px > cut_radius_px && !black) ++lit_outside;
    }
  }
  EXPECT_EQ(black_inside, 0);
  EXPECT_EQ(lit_outside, 0);
  EXPECT_GT(blobOf(frame.image, kRed).pixels, 20);
  EXPECT_EQ(blobOf(frame.image, kGreen).pixels, 0) << "80 degrees is beyond the cutoff";
  EXPECT_EQ(blobOf(frame.image, kBlue).pixels, 0) << "100 degrees is beyond the cutoff";
  // Without a cutoff inside the image, the corners (theta 137 degrees) are not black.
  const Frame full = render(wideAngleFixtureWith(), {});
  EXPECT_FALSE(isBlack(pixel(full.image, 0, 0)));
  EXPECT_FALSE(isBlack(pixel(full.image, kWidth - 1, kHeight - 1)));
}

TEST(WideAngleCamera, TheEquidistantLensPutsTheRadiusInProportionToTheAngle) {
  // equidistant: r = theta (c1 = c2 = f = 1, id), scaled so that r = 1 at hfov / 2 = 1.5.
  const std::string urdf = wideAngleFixtureWith(
      {{"<type>custom</type>", "<type>equidistant</type>"},
       {"<horizontal_fov>4.0<", "<horizontal_fov>3.0<"}});
  const std::vector<double> angles = {0.3, 0.6, 0.9, 1.2};
  const Eigen::Vector4f colours[] = {kRed, kGreen, kBlue, kYellow};
  std::vector<Target> targets;
  for (size_t i = 0; i < angles.size(); ++i) targets.push_back({angles[i], 0, colours[i]});
  const Frame frame = render(urdf, targets);
  for (size_t i = 0; i < angles.size(); ++i) {
    const double r_px = kHalfWidth * angles[i] / 1.5;  // 32, 64, 96, 128 px
    expectBlobAt(frame.image, colours[i], kHalfWidth - r_px, kHeight / 2.0,
                 "the box " + std::to_string(angles[i]) + " rad left");
  }
}

TEST(WideAngleCamera, PointLightsLightItsCubeFacesPerPixel) {
  // A grey box face 2.9 m ahead on the axis, ambient 0.1, the sun behind it; an AutoRace
  // lamp (diffuse 0.5, attenuation 0.5 / 0.01 / 0.001) 0.5 m in front of the face.
  bullet_sim::WorldSpec world;
  world.ambient = Eigen::Vector4f(0.1f, 0.1f, 0.1f, 1.0f);
  world.shapes.push_back(boxAt({0, 0, Eigen::Vector4f(0.5f, 0.5f, 0.5f, 1)}, 0));
  bullet_sim::LightSpec lamp;
  lamp.pose.position = kCamera + Vector3d(kDistance - 0.1 - 0.5, 0, 0);
  lamp.diffuse = Eigen::Vector4f(0.5f, 0.5f, 0.5f, 1);
  lamp.range_m = 20;
  lamp.constant = 0.5;
  lamp.linear = 0.01;
  lamp.quadratic = 0.001;
  auto centre = [](const bullet_sim::WorldSpec& w) {
    bullet_sim::Simulation sim(w, bullet_sim::SimConfig{});
    sim.spawnRobot("wide_bot", bullet_sim::parseRobot(wideAngleFixtureWith(), "wide_angle_robot.urdf"),
                   Pose3{});
    bullet_sim::CameraRenderer renderer(sim);
    ImageData image;
    renderer.render("wide_bot", 0, &image);
    return static_cast<int>(pixel(image, kWidth / 2, kHeight / 2)[0]);
  };
  // Without the lamp: 0.5 x 0.1 = 0.05 -> 13.
  EXPECT_EQ(centre(world), 13);
  // With it, on the axis: d = 0.5, cos = 1, 1 / (0.5 + 0.005 + 0.00025) = 1.979218;
  // 0.5 (0.1 + 0.5 x 1.979218) = 0.544805 -> 139.
  world.lights.push_back(lamp);
  EXPECT_NEAR(centre(world), 139, 1);
}

TEST(WideAngleCamera, CameraInfoIsThePinholeThatMatchesTheLensNearItsAxis) {
  const Frame frame = render(wideAngleFixtureWith(), {});
  // dr/dtheta at 0 = c1 f / c2 = 1.05 / (1.05 tan(0.5)) / 4, in half widths per radian.
  const double fx = kHalfWidth / (4 * std::tan(4.0 / 8));
  EXPECT_NEAR(frame.info.K[0], fx, 1e-9);
  EXPECT_NEAR(frame.info.K[4], fx, 1e-9);
  EXPECT_NEAR(frame.info.P[0], fx, 1e-9);
  EXPECT_DOUBLE_EQ(frame.info.K[2], kWidth / 2.0);
  EXPECT_DOUBLE_EQ(frame.info.K[5], kHeight / 2.0);
}

TEST(WideAngleCamera, OnlyTheCubeFacesTheLensSeesAreRendered) {
  bullet_sim::CameraSpec camera =
      bullet_sim::parseRobot(wideAngleFixtureWith(), "wide_angle_robot.urdf").cameras.at(0);
  // hfov 4.0: the corners look 137 degrees off the axis, so the face behind is needed.
  EXPECT_EQ(bullet_sim::LensCamera(camera).facesRendered(), 6);
  // The autorace camera (hfov 3.183): corners at 111 degrees, nothing behind.
  camera.horizontal_fov_rad = 3.183;
  EXPECT_EQ(bullet_sim::LensCamera(camera).facesRendered(), 5);
  // Cut off at 40 degrees: the forward face alone.
  camera.lens->cutoff_angle_rad = 40 * kDeg;
  EXPECT_EQ(bullet_sim::LensCamera(camera).facesRendered(), 1);
}

TEST(WideAngleCamera, AHandMadeBadLensIsRefusedNamingTheCameraAndTheValue) {
  bullet_sim::CameraSpec camera =
      bullet_sim::parseRobot(wideAngleFixtureWith(), "wide_angle_robot.urdf").cameras.at(0);
  EXPECT_NO_THROW(bullet_sim::validateCamera(camera));
  camera.lens->env_texture_size = 3;
  try {
    bullet_sim::validateCamera(camera);
    ADD_FAILURE() << "no error";
  } catch (const bullet_sim::LoadError& e) {
    EXPECT_STREQ(e.what(), "camera 'camera' on link 'camera_link': <lens> <env_texture_size>: 3 "
                           "is not a pixel count in 4..2048");
  }
  camera.lens->env_texture_size = 256;
  camera.lens->fun = "cos";
  camera.lens->type = "custom";
  EXPECT_THROW(bullet_sim::validateCamera(camera), bullet_sim::LoadError);
}

TEST(WideAngleCamera, FrameTimeOfTheAutoraceCamera) {
  bullet_sim::CameraSpec camera =
      bullet_sim::parseRobot(wideAngleFixtureWith(), "wide_angle_robot.urdf").cameras.at(0);
  camera.horizontal_fov_rad = 3.183;
  camera.lens->env_texture_size = 512;
  bullet_sim::LensCamera lens_camera(camera);
  sim_render::Scene scene;
  for (int i = 0; i < 4; ++i) {
    scene.add(sim_render::ShapeSpec::box(0.2, 0.2, 0.2, {1, 0, 0, 1}),
              Eigen::Isometry3d(Eigen::Translation3d(std::cos(i), std::sin(i), 0.5)));
  }
  std::vector<uint8_t> rgb;
  lens_camera.render(scene, Eigen::Isometry3d::Identity(), rgb);
  constexpr int kFrames = 5;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kFrames; ++i) lens_camera.render(scene, Eigen::Isometry3d::Identity(), rgb);
  const double ms = std::chrono::duration<double, std::milli>(
                        std::chrono::steady_clock::now() - start).count() / kFrames;
  std::cout << "autorace wide-angle camera (320x240, 5 faces of 512x512): " << ms
            << " ms per frame\n";
  EXPECT_EQ(rgb.size(), static_cast<size_t>(kWidth * kHeight * 3));
}

}  // namespace
