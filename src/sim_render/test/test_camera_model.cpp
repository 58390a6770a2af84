#include "sim_render/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using sim_render::CameraModel;

namespace {

std::string validationError(const CameraModel& camera) {
  try {
    camera.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CameraModel, BurgerCameraInfoFollowsTheFov) {
  CameraModel camera;  // 640 x 480, hfov 1.5707
  // tan(1.5707 / 2) = 0.99990367, so fx = 320 / 0.99990367.
  const double fx = 320.0308261;
  const auto K = camera.K();
  const double expected_K[9] = {fx, 0, 320, 0, fx, 240, 0, 0, 1};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(K[i], expected_K[i], 1e-6) << "K[" << i << "]";
  const auto P = camera.P();
  const double expected_P[12] = {fx, 0, 320, 0, 0, fx, 240, 0, 0, 0, 1, 0};
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(P[i], expected_P[i], 1e-6) << "P[" << i << "]";
}

TEST(CameraModel, NinetyDegreeFovGivesHalfWidthFocalLength) {
  CameraModel camera;
  camera.width = 800;
  camera.height = 600;
  camera.horizontal_fov_rad = M_PI / 2;
  EXPECT_NEAR(camera.fx(), 400.0, 1e-9);
  EXPECT_NEAR(camera.fy(), 400.0, 1e-9);
  EXPECT_DOUBLE_EQ(camera.cx(), 400.0);
  EXPECT_DOUBLE_EQ(camera.cy(), 300.0);
}

TEST(CameraModel, ProjectsWithGazeboAxes) {
  CameraModel camera;
  camera.horizontal_fov_rad = M_PI / 2;  // fx = fy = 320
  Eigen::Vector2d uv;
  // +y is the image's left, +z its top.
  ASSERT_TRUE(camera.project(Eigen::Vector3d(2.0, 0.5, -0.25), &uv));
  EXPECT_NEAR(uv.x(), 320 - 320 * 0.25, 1e-9);
  EXPECT_NEAR(uv.y(), 240 + 320 * 0.125, 1e-9);
  EXPECT_FALSE(camera.project(Eigen::Vector3d(-1.0, 0, 0), &uv));
  EXPECT_FALSE(camera.project(Eigen::Vector3d(0.0, 1, 0), &uv));
}

TEST(CameraModel, ValidationNamesTheBadValue) {
  CameraModel ok;
  EXPECT_EQ(validationError(ok), "");

  CameraModel c = ok;
  c.width = 0;
  EXPECT_NE(validationError(c).find("width = 0"), std::string::npos) << validationError(c);
  c = ok;
  c.height = -3;
  EXPECT_NE(validationError(c).find("height = -3"), std::string::npos) << validationError(c);
  c = ok;
  c.horizontal_fov_rad = 3.5;
  EXPECT_NE(validationError(c).find("horizontal_fov_rad = 3.5"), std::string::npos) << validationError(c);
  c = ok;
  c.clip_near_m = 0;
  EXPECT_NE(validationError(c).find("clip_near_m = 0"), std::string::npos) << validationError(c);
  c = ok;
  c.clip_far_m = 0.01;
  EXPECT_NE(validationError(c).find("clip_far_m = 0.01"), std::string::npos) << validationError(c);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
