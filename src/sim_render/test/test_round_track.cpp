// The round-track world seen by the Burger's camera: walls, floor and start line must appear
// where projecting their known geometry (DESIGN.md) through K puts them.
#include "render_test_util.h"
#include "round_track_scene.h"
#include "sim_render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sim_render;
using namespace sim_render::test;

namespace {

// The Burger's camera (turtlebot3_burger.gazebo.xacro): 640 x 480, hfov 1.5707, clip 0.02..100.
CameraModel burgerCamera() {
  CameraModel camera;
  camera.width = 640;
  camera.height = 480;
  camera.horizontal_fov_rad = 1.5707;
  camera.clip_near_m = 0.02;
  camera.clip_far_m = 100;
  return camera;
}

// Colours by hand from the world's light: direction (-0.5, 0.1, -0.9), diffuse 0.8, ambient
// 0.4, sky 0.7. |direction| = 1.034408.
const double kLightNorm = std::sqrt(0.25 + 0.01 + 0.81);
const Rgb kSky = expectedRgb(0.7, 0.7, 0.7);
const Rgb kFloor = expectedRgb(0.5 * (0.4 + 0.8 * 0.9 / kLightNorm), 0.5 * (0.4 + 0.8 * 0.9 / kLightNorm),
                               0.5 * (0.4 + 0.8 * 0.9 / kLightNorm));
// Left wall face looks +x (towards the light), right wall face looks -x (ambient only).
const double kLitWall = 0.4 + 0.8 * 0.5 / kLightNorm;
const Rgb kLeftWall = expectedRgb(0.57 * kLitWall, 0.417 * kLitWall, 0.25 * kLitWall);
const Rgb kRightWall = expectedRgb(0.57 * 0.4, 0.417 * 0.4, 0.25 * 0.4);

// Inner faces of the lane's walls (centres x -0.80941 and 0.54193, 0.015 m thick).
const double kLeftWallFace_x = -0.80941 + 0.0075;
const double kRightWallFace_x = 0.54193 - 0.0075;

// The start line's face towards the robot looks along -y: the light's -0.1 y component
// reaches it at a grazing angle.
const double kLineNearLight = 0.4 + 0.8 * 0.1 / kLightNorm;
const Rgb kLineNearFace = expectedRgb(kLineNearLight, kLineNearLight, kLineNearLight);
const Rgb kWhite{255, 255, 255};  // the line's top face: 1 * (0.4 + 0.8 * 0.87) saturates

// Middle of the start line's near face (local -x side) where it reaches world x = wall_x.
Eigen::Vector3d nearFaceMiddleAt(const Eigen::Isometry3d& T_world_line, double wall_x) {
  const double half_thickness = 0.5 * round_track::kStartLineSize.x();
  const Eigen::Matrix3d R = T_world_line.linear();
  const double s = (wall_x - T_world_line.translation().x() + R(0, 0) * half_thickness) / R(0, 1);
  return T_world_line * Eigen::Vector3d(-half_thickness, s, 0);
}

struct Frame {
  CameraModel camera = burgerCamera();
  Eigen::Isometry3d T_camera_world;
  std::vector<std::uint8_t> image;
};

Frame renderRobotAt(double x, double y) {
  Scene scene;
  round_track::addWorld(scene);
  const Eigen::Isometry3d T_world_base = round_track::baseLinkPose(x, y, round_track::kSpawnYaw_rad);
  round_track::addRobot(scene, T_world_base);
  Frame frame;
  const Eigen::Isometry3d T_world_camera = round_track::cameraPose(T_world_base);
  frame.T_camera_world = T_world_camera.inverse();
  Renderer renderer(frame.camera);
  renderer.render(scene, T_world_camera, frame.image);
  return frame;
}

Eigen::Vector2d project(const Frame& frame, const Eigen::Vector3d& p_world) {
  Eigen::Vector2d uv(NAN, NAN);
  EXPECT_TRUE(frame.camera.project(frame.T_camera_world * p_world, &uv)) << p_world.transpose();
  return uv;
}

// Row where the image of the 3D segment p0-p1 crosses column `col` (a 3D line projects to a line).
double edgeRowAt(const Frame& frame, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, int col) {
  const Eigen::Vector2d a = project(frame, p0), b = project(frame, p1);
  return a.y() + (col - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
}

// First row in column `col`, searching down from `from_row`, that has colour `below`, the row
// above it having colour `above`; -1 when there is none.
int transitionRow(const Frame& frame, int col, int from_row, int to_row, const Rgb& above, const Rgb& below) {
  for (int row = std::max(from_row, 1); row <= std::min(to_row, 479); ++row) {
    if (pixel(frame.image, 640, col, row - 1) == above && pixel(frame.image, 640, col, row) == below) return row;
  }
  return -1;
}

// Checks that the boundary between `above` and `below` in column col is at the projected row.
void expectEdge(const Frame& frame, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, int col,
                const Rgb& above, const Rgb& below, const char* what) {
  const double v = edgeRowAt(frame, p0, p1, col);
  const int row = transitionRow(frame, col, static_cast<int>(v) - 10, static_cast<int>(v) + 10, above, below);
  ASSERT_GE(row, 0) << what << ": no transition near row " << v << " in column " << col;
  // The first pixel below the edge has its centre within one pixel of the edge.
  EXPECT_NEAR(row, v + 0.5, 1.0) << what << " in column " << col;
}

}  // namespace

TEST(RoundTrack, CameraInfoOfTheBurgerCamera) {
  const CameraModel camera = burgerCamera();
  const double f = 320.0 / std::tan(1.5707 / 2);
  const auto K = camera.K();
  EXPECT_NEAR(K[0], f, 1e-9);
  EXPECT_NEAR(K[4], f, 1e-9);
  EXPECT_NEAR(K[2], 320.0, 1e-12);
  EXPECT_NEAR(K[5], 240.0, 1e-12);
  const auto P = camera.P();
  EXPECT_NEAR(P[0], f, 1e-9);
  EXPECT_NEAR(P[5], f, 1e-9);
  EXPECT_EQ(P[3], 0.0);
  EXPECT_EQ(P[7], 0.0);
}

TEST(RoundTrack, WallsAndFloorAtTheSpawnPoseAreWhereKPutsThem) {
  const Frame frame = renderRobotAt(0, 0);
  const double left_x = kLeftWallFace_x, right_x = kRightWallFace_x;
  for (int col : {40, 120, 200}) {
    expectEdge(frame, {left_x, 1.0, 0.5}, {left_x, 2.5, 0.5}, col, kSky, kLeftWall, "left wall top");
    expectEdge(frame, {left_x, 1.0, 0.0}, {left_x, 2.5, 0.0}, col, kLeftWall, kFloor, "left wall bottom");
  }
  for (int col : {440, 520, 600}) {
    expectEdge(frame, {right_x, 1.0, 0.5}, {right_x, 2.0, 0.5}, col, kSky, kRightWall, "right wall top");
    expectEdge(frame, {right_x, 1.0, 0.0}, {right_x, 2.0, 0.0}, col, kRightWall, kFloor, "right wall bottom");
  }
  // The start line is in front of the robot but below the field of view: every corner of it
  // projects under the last row, so no pixel shows it.
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner_local(0.5 * round_track::kStartLineSize.x() * ((i & 1) ? 1 : -1),
                                       0.5 * round_track::kStartLineSize.y() * ((i & 2) ? 1 : -1),
                                       0.5 * round_track::kStartLineSize.z() * ((i & 4) ? 1 : -1));
    EXPECT_GT(project(frame, round_track::startLinePose() * corner_local).y(), 480.0);
  }
  for (int row = 0; row < 480; ++row) {
    for (int col = 0; col < 640; ++col) ASSERT_NE(pixel(frame.image, 640, col, row), kWhite);
  }
}

TEST(RoundTrack, StartLineIsWhereKPutsItWhenInView) {
  // 0.3 m and 0.8 m behind the spawn point the line is in view.
  for (double y : {-0.3, -0.8}) {
    const Frame frame = renderRobotAt(0, y);
    const Eigen::Isometry3d T_world_line = round_track::startLinePose();
    const Eigen::Vector3d h = 0.5 * round_track::kStartLineSize;
    // Local +x points away from the camera (yaw ~ pi/2): the far top edge is the upper
    // silhouette, the near bottom edge the lower one.
    const Eigen::Vector3d far_top0 = T_world_line * Eigen::Vector3d(h.x(), -0.5, h.z());
    const Eigen::Vector3d far_top1 = T_world_line * Eigen::Vector3d(h.x(), 0.5, h.z());
    const Eigen::Vector3d near_bottom0 = T_world_line * Eigen::Vector3d(-h.x(), -0.5, -h.z());
    const Eigen::Vector3d near_bottom1 = T_world_line * Eigen::Vector3d(-h.x(), 0.5, -h.z());
    // The line runs into the walls: its near face is visible between the walls' inner faces.
    const Eigen::Vector2d left_end = project(frame, nearFaceMiddleAt(T_world_line, kLeftWallFace_x));
    const Eigen::Vector2d right_end = project(frame, nearFaceMiddleAt(T_world_line, kRightWallFace_x));
    const double u_left = left_end.x(), u_right = right_end.x();
    ASSERT_LT(u_left, u_right);
    for (int i = 0; i <= 4; ++i) {
      const double u_begin = std::max(u_left, 0.0) + 10, u_end = std::min(u_right, 639.0) - 10;
      const int col = static_cast<int>(std::lround(u_begin + i * (u_end - u_begin) / 4));
      const double v_top = edgeRowAt(frame, far_top0, far_top1, col);
      const double v_bottom = edgeRowAt(frame, near_bottom0, near_bottom1, col);
      ASSERT_GT(v_top, 300.0);
      ASSERT_LT(v_bottom, 479.0);
      int first = -1, last = -1;
      for (int row = static_cast<int>(v_top) - 4; row < std::min(480, static_cast<int>(v_bottom) + 4); ++row) {
        const Rgb p = pixel(frame.image, 640, col, row);
        if (p == kWhite || p == kLineNearFace) {
          if (first < 0) first = row;
          last = row;
        }
      }
      ASSERT_GE(first, 0) << "no start line in column " << col << " at y " << y;
      EXPECT_NEAR(first, v_top + 0.5, 1.0) << "top edge, column " << col << ", y " << y;
      EXPECT_NEAR(last, v_bottom - 0.5, 1.0) << "bottom edge, column " << col << ", y " << y;
      // Its top face is white (lit from above).
      EXPECT_EQ(pixel(frame.image, 640, col, first), kWhite);
    }
    // Where the line meets the walls, inside the image: wall on one side, line on the other.
    if (u_left > 3) {
      const int row = static_cast<int>(std::lround(left_end.y()));
      EXPECT_EQ(pixel(frame.image, 640, static_cast<int>(u_left) - 2, row), kLeftWall) << "y " << y;
      EXPECT_EQ(pixel(frame.image, 640, static_cast<int>(u_left) + 3, row), kLineNearFace) << "y " << y;
    }
    if (u_right < 636) {
      const int row = static_cast<int>(std::lround(right_end.y()));
      EXPECT_EQ(pixel(frame.image, 640, static_cast<int>(u_right) + 3, row), kRightWall) << "y " << y;
      EXPECT_EQ(pixel(frame.image, 640, static_cast<int>(u_right) - 2, row), kLineNearFace) << "y " << y;
    }
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
