// Small helpers for reading rendered images in tests.
#pragma once

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sim_render {
namespace test {

using Rgb = std::array<int, 3>;

inline Rgb pixel(const std::vector<std::uint8_t>& image, int width, int col, int row) {
  const std::size_t i = (static_cast<std::size_t>(row) * width + col) * 3;
  return {image[i], image[i + 1], image[i + 2]};
}

/// The byte a renderer should write for a linear value, computed by hand: round(clamp * 255).
inline Rgb expectedRgb(double r, double g, double b) {
  auto byte = [](double v) { return static_cast<int>(std::lround(std::min(1.0, std::max(0.0, v)) * 255.0)); };
  return {byte(r), byte(g), byte(b)};
}

/// Camera pose: position and yaw/pitch (pitch > 0 looks down, Gazebo's convention).
inline Eigen::Isometry3d cameraAt(const Eigen::Vector3d& position, double yaw = 0.0, double pitch_down = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = position;
  T.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch_down, Eigen::Vector3d::UnitY())).toRotationMatrix();
  return T;
}

inline Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

}  // namespace test
}  // namespace sim_render
