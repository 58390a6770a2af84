// The Burger's camera on the real round track: camera_info from the fov, and walls, floor
// and start line where projecting their known geometry (DESIGN.md's figures) puts them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../core/burger.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/simulation.h"

namespace {

using bullet_sim::CameraRenderer;
using bullet_sim::ImageData;
using bullet_sim::Pose3;
using bullet_sim::Simulation;
using Eigen::Vector3d;

constexpr double kSpawnYaw = 1.5675;
constexpr double kHfov = 1.5707;
constexpr int kWidth = 640, kHeight = 480;
// base_footprint -> base_link 0.010 up, base_link -> camera_link (0.02, 0, 0.295).
const Vector3d kCameraInBase(0.02, 0, 0.010 + 0.295);
constexpr double kWallHalfThickness = 0.0075, kWallHeight = 0.5;

struct Wall {
  double x, y, yaw, length;
};
// From DESIGN.md's wall table: the lane's west and east walls and the one across its end.
constexpr Wall kWestWall{-0.80941, 0.25461, 0, 6.0};
constexpr Wall kEastWall{0.54193, 0.34703, 0, 3.8};
constexpr Wall kNorthWall{0.196982, 3.258921, 1.57467, 2.0};

// Start line: box 0.015 x 1.5 x 0.015 at (-0.1, 0.333, 0.022), yaw 1.5687.
const Vector3d kLineCentre(-0.1, 0.333, 0.022);
constexpr double kLineYaw = 1.5687, kLineHalf = 0.0075;

double focal() { return (kWidth / 2.0) / std::tan(kHfov / 2.0); }

Eigen::Matrix3d yawMatrix(double yaw) { return Eigen::AngleAxisd(yaw, Vector3d::UnitZ()).matrix(); }

/// The camera as DESIGN.md places it: robot base at (x, y, 0) with yaw, camera level.
struct Camera {
  Vector3d position;
  Eigen::Matrix3d R_world_camera;
  Camera(double x, double y, double yaw)
      : position(Vector3d(x, y, 0) + yawMatrix(yaw) * kCameraInBase),
        R_world_camera(yawMatrix(yaw)) {}

  Vector3d toCamera(const Vector3d& p_world) const {
    return R_world_camera.transpose() * (p_world - position);
  }
  /// Row at which the world line p0 + s dir crosses image column `col` (Gazebo
  /// convention: u = cx - f y / x, v = cy - f z / x).
  double rowOfLineAtColumn(const Vector3d& p0_world, const Vector3d& dir_world, double col) const {
    const Vector3d a = toCamera(p0_world);
    const Vector3d b = R_world_camera.transpose() * dir_world;
    const double k = kWidth / 2.0 - col;  // (cx - u) x - f y = 0, linear in s
    const double s = -(k * a.x() - focal() * a.y()) / (k * b.x() - focal() * b.y());
    const Vector3d p = a + s * b;
    return kHeight / 2.0 - focal() * p.z() / p.x();
  }
};

/// Row of a wall's edge at height z on the face turned towards the camera.
double wallEdgeRow(const Camera& cam, const Wall& wall, double z, double col) {
  const Eigen::Matrix3d R = yawMatrix(wall.yaw);
  const Vector3d centre(wall.x, wall.y, z);
  const Vector3d normal = R * Vector3d::UnitX();
  const double side = normal.dot(cam.position - centre) > 0 ? 1.0 : -1.0;
  return cam.rowOfLineAtColumn(centre + side * kWallHalfThickness * normal, R * Vector3d::UnitY(),
                               col);
}

/// Row of a long edge of the start line: `along` -1 front (towards -y), +1 back; `up` likewise.
double lineEdgeRow(const Camera& cam, double along, double up, double col) {
  const Eigen::Matrix3d R = yawMatrix(kLineYaw);
  const Vector3d p0 = kLineCentre + R * Vector3d(along * kLineHalf, 0, up * kLineHalf);
  return cam.rowOfLineAtColumn(p0, R * Vector3d::UnitY(), col);
}

struct Rgb {
  int r, g, b;
};
Rgb pixel(const ImageData& image, int col, int row) {
  const size_t i = static_cast<size_t>(row) * image.step + 3 * static_cast<size_t>(col);
  return {image.data[i], image.data[i + 1], image.data[i + 2]};
}
// Cardboard (0.57 0.417 0.25) under any light: red over green over blue.
bool isWall(const Rgb& p) { return p.r > p.g + 8 && p.g > p.b + 8; }
bool isGrey(const Rgb& p) { return std::abs(p.r - p.g) <= 2 && std::abs(p.g - p.b) <= 2; }
bool isWhite(const Rgb& p) { return p.r >= 230 && p.g >= 230 && p.b >= 230; }
bool same(const Rgb& a, const Rgb& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/// First and last row of column `col` within [from, to] where `pred` holds; -1 when none.
template <typename Pred>
std::pair<int, int> rowSpan(const ImageData& image, int col, int from, int to, Pred pred) {
  int first = -1, last = -1;
  for (int row = std::max(0, from); row <= std::min(kHeight - 1, to); ++row) {
    if (!pred(pixel(image, col, row))) continue;
    if (first < 0) first = row;
    last = row;
  }
  return {first, last};
}

int countPixels(const ImageData& image, bool (*pred)(const Rgb&)) {
  int n = 0;
  for (int row = 0; row < image.height; ++row)
    for (int col = 0; col < image.width; ++col) n += pred(pixel(image, col, row)) ? 1 : 0;
  return n;
}

class RoundTrackCamera : public ::testing::Test {
 protected:
  RoundTrackCamera()
      : sim_(bullet_sim::loadWorldFile(bullet_sim_test::roundTrackPath()), bullet_sim::SimConfig()),
        renderer_(sim_) {
    sim_.spawnRobot("burger", bullet_sim_test::burgerSpec(), basePose(0, 0));
  }

  static Pose3 basePose(double x, double y) {
    Pose3 pose;
    pose.position = {x, y, 0};
    pose.orientation = Eigen::AngleAxisd(kSpawnYaw, Vector3d::UnitZ());
    return pose;
  }

  /// Puts the robot at (x, y, yaw kSpawnYaw) and renders; checks the camera link is where
  /// DESIGN.md's joint table puts it, so the expected rows below hold.
  ImageData renderAt(double x, double y) {
    sim_.setModelState("burger", basePose(x, y), bullet_sim::Twist3());
    const Camera cam(x, y, kSpawnYaw);
    for (const bullet_sim::LinkPose& link : sim_.linkPoses("burger")) {
      if (link.link == "camera_link") {
        EXPECT_LT((link.pose.position - cam.position).norm(), 1e-3);
      }
    }
    ImageData image;
    renderer_.render("burger", 0, &image);
    return image;
  }

  Simulation sim_;
  CameraRenderer renderer_;
};

TEST_F(RoundTrackCamera, CameraInfoFollowsTheFov) {
  const bullet_sim::CameraSpec& spec = sim_.robotSpec("burger").cameras.at(0);
  const bullet_sim::CameraInfoData info = bullet_sim::cameraInfo(spec, 2.5);
  const double f = 320.0 / std::tan(1.5707 / 2);  // 320.03
  EXPECT_NEAR(info.K[0], f, 1e-9);
  EXPECT_NEAR(info.K[4], f, 1e-9);
  EXPECT_DOUBLE_EQ(info.K[2], 320);
  EXPECT_DOUBLE_EQ(info.K[5], 240);
  EXPECT_DOUBLE_EQ(info.K[8], 1);
  EXPECT_DOUBLE_EQ(info.K[1], 0);
  EXPECT_NEAR(info.P[0], f, 1e-9);
  EXPECT_NEAR(info.P[5], f, 1e-9);
  EXPECT_DOUBLE_EQ(info.P[2], 320);
  EXPECT_DOUBLE_EQ(info.P[6], 240);
  EXPECT_DOUBLE_EQ(info.P[3], 0);
  EXPECT_DOUBLE_EQ(info.P[10], 1);
  for (double d : info.D) EXPECT_EQ(d, 0);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_EQ(info.frame_id, "camera_optical_link");
  EXPECT_EQ(info.time_s, 2.5);
}

TEST_F(RoundTrackCamera, ImageHeader) {
  for (int i = 0; i < 7; ++i) sim_.step();
  ImageData image;
  renderer_.render("burger", 0, &image);
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 480);
  EXPECT_EQ(image.encoding, "rgb8");
  EXPECT_EQ(image.step, 640 * 3);
  EXPECT_EQ(image.data.size(), 640u * 480u * 3u);
  EXPECT_EQ(image.frame_id, "camera_optical_link");
  EXPECT_NEAR(image.time_s, sim_.timeS(), 1e-12);
  EXPECT_TRUE(renderer_.warnings().empty());
}

TEST_F(RoundTrackCamera, WallsAtTheSpawnPoseWhereProjectionPutsThem) {
  const ImageData image = renderAt(0, 0);
  const Camera cam(0, 0, kSpawnYaw);
  const struct {
    const Wall* wall;
    std::vector<int> cols;
  } views[] = {{&kWestWall, {10, 60, 120, 180, 230}},
               {&kNorthWall, {280, 320, 360}},
               {&kEastWall, {420, 480, 560, 630}}};
  for (const auto& view : views) {
    for (int col : view.cols) {
      SCOPED_TRACE("column " + std::to_string(col));
      const double top = wallEdgeRow(cam, *view.wall, kWallHeight, col);
      const double bottom = wallEdgeRow(cam, *view.wall, 0, col);
      const auto span = rowSpan(image, col, 0, kHeight - 1, isWall);
      EXPECT_NEAR(span.first, top, 2.0);
      EXPECT_NEAR(span.second, bottom, 2.0);
      // Sky right above the wall's top, floor right under its foot.
      const Rgb above = pixel(image, col, static_cast<int>(std::floor(top)) - 2);
      const Rgb below = pixel(image, col, static_cast<int>(std::ceil(bottom)) + 2);
      EXPECT_TRUE(isGrey(above) && above.r > 160) << above.r << " " << above.g << " " << above.b;
      EXPECT_TRUE(isGrey(below) && below.r < 160) << below.r << " " << below.g << " " << below.b;
    }
  }
}

TEST_F(RoundTrackCamera, FloorBelowTheFarWallAndNoStartLineAtTheSpawnPose) {
  const ImageData image = renderAt(0, 0);
  const Camera cam(0, 0, kSpawnYaw);
  // The floor is one plane under one light: one colour from the far wall's foot down.
  const int foot = static_cast<int>(std::ceil(wallEdgeRow(cam, kNorthWall, 0, 320)));
  const Rgb floor = pixel(image, 320, kHeight - 1);
  EXPECT_TRUE(isGrey(floor));
  for (int col : {250, 320, 390}) {
    for (int row = foot + 2; row < kHeight; ++row) {
      ASSERT_TRUE(same(pixel(image, col, row), floor)) << "col " << col << " row " << row;
    }
  }
  // The line lies 0.31 m ahead of the camera; the lowest row sees the floor 0.41 m ahead.
  EXPECT_GT(lineEdgeRow(cam, -1, -1, 320), kHeight + 20);
  EXPECT_EQ(countPixels(image, isWhite), 0);
}

TEST_F(RoundTrackCamera, StartLineWhereProjectionPutsItFromBehind) {
  for (double y : {-0.3, -0.5, -0.8}) {
    SCOPED_TRACE("robot at y " + std::to_string(y));
    const ImageData image = renderAt(0, y);
    const Camera cam(0, y, kSpawnYaw);
    const Rgb floor = pixel(image, 320, kHeight - 1);
    // Columns whose rays meet the line between the lane's walls from every distance.
    for (int col : {160, 240, 320, 400}) {
      SCOPED_TRACE("column " + std::to_string(col));
      const double back_top = lineEdgeRow(cam, +1, +1, col);
      const double front_top = lineEdgeRow(cam, -1, +1, col);
      const double front_bottom = lineEdgeRow(cam, -1, -1, col);
      ASSERT_LT(front_bottom, kHeight - 5);
      // The box covers rows from its top back edge to its bottom front edge ...
      const auto box = rowSpan(image, col, static_cast<int>(back_top) - 15,
                               static_cast<int>(front_bottom) + 15,
                               [&](const Rgb& p) { return !same(p, floor); });
      EXPECT_NEAR(box.first, back_top, 3.0);
      EXPECT_NEAR(box.second, front_bottom, 3.0);
      // ... and its white (lit) top face lies between its two top edges.
      const auto white = rowSpan(image, col, 0, kHeight - 1, isWhite);
      ASSERT_GE(white.first, 0);
      EXPECT_NEAR(white.first, back_top, 3.0);
      EXPECT_NEAR(white.second, front_top, 3.0);
    }
  }
}

TEST_F(RoundTrackCamera, AnotherRobotAppearsAndGoesAway) {
  const ImageData alone = renderAt(0, 0);
  sim_.spawnRobot("other", bullet_sim_test::burgerSpec(), basePose(0, 1.0));
  ImageData with_other;
  renderer_.render("burger", 0, &with_other);
  // Its body is dark grey; the middle column crosses it just under the horizon.
  const auto dark = rowSpan(with_other, 320, 240, kHeight - 1,
                            [](const Rgb& p) { return p.r < 100 && isGrey(p); });
  EXPECT_GE(dark.first, 240);
  EXPECT_NE(alone.data, with_other.data);
  ASSERT_TRUE(sim_.deleteRobot("other"));
  ImageData again;
  renderer_.render("burger", 0, &again);
  EXPECT_EQ(alone.data, again.data);
}

TEST(CameraFormats, EncodingsAndValidation) {
  bullet_sim::CameraSpec camera;
  camera.name = "cam";
  camera.link = "head";
  EXPECT_EQ(bullet_sim::imageEncoding(camera), "rgb8");
  camera.format = "B8G8R8";
  EXPECT_EQ(bullet_sim::imageEncoding(camera), "bgr8");
  camera.format = "L8";
  EXPECT_EQ(bullet_sim::imageEncoding(camera), "mono8");
  camera.format = "R16G16B16";
  EXPECT_EQ(bullet_sim::imageEncoding(camera), "rgb16");
  camera.format = "L16";
  EXPECT_EQ(bullet_sim::imageEncoding(camera), "mono16");
  camera.format = "BAYER_RGGB8";
  try {
    bullet_sim::validateCamera(camera);
    FAIL() << "BAYER_RGGB8 accepted";
  } catch (const bullet_sim::LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("camera 'cam' on link 'head'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("'BAYER_RGGB8'"), std::string::npos);
  }
  camera.format = "R8G8B8";
  camera.width = 0;
  try {
    bullet_sim::validateCamera(camera);
    FAIL() << "width 0 accepted";
  } catch (const bullet_sim::LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("width"), std::string::npos) << e.what();
  }
}

TEST_F(RoundTrackCamera, BgrAndMonoAreTheSamePicture) {
  ImageData rgb;
  renderer_.render("burger", 0, &rgb);
  bullet_sim::RobotSpec spec = bullet_sim_test::burgerSpec();
  spec.cameras.at(0).format = "B8G8R8";
  sim_.spawnRobot("bgr", spec, basePose(0, 0));
  spec.cameras.at(0).format = "L8";
  sim_.spawnRobot("mono", spec, basePose(0, 0));
  ImageData bgr, mono;
  renderer_.render("bgr", 0, &bgr);
  renderer_.render("mono", 0, &mono);
  ASSERT_EQ(bgr.encoding, "bgr8");
  ASSERT_EQ(mono.encoding, "mono8");
  EXPECT_EQ(mono.step, 640);
  ASSERT_EQ(mono.data.size(), 640u * 480u);
  for (size_t i : {0ul, 100000ul, 200000ul, 307199ul}) {
    EXPECT_EQ(bgr.data[3 * i], rgb.data[3 * i + 2]);
    EXPECT_EQ(bgr.data[3 * i + 2], rgb.data[3 * i]);
    const double y = 0.299 * rgb.data[3 * i] + 0.587 * rgb.data[3 * i + 1] + 0.114 * rgb.data[3 * i + 2];
    EXPECT_NEAR(mono.data[i], y, 0.5 + 1e-9);
  }
}

TEST_F(RoundTrackCamera, UnknownRobotOrCamera) {
  ImageData image;
  EXPECT_THROW(renderer_.render("nobody", 0, &image), std::out_of_range);
  EXPECT_THROW(renderer_.render("burger", 1, &image), std::out_of_range);
}

}  // namespace
