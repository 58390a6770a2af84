/// @file camera_model.h
/// @brief Pinhole camera with Gazebo's frame convention and ROS camera_info matrices.
#pragma once

#include <Eigen/Core>

#include <array>

namespace sim_render {

/// A pinhole camera as Gazebo's camera sensor defines it.
///
/// Frame convention: the camera looks along its frame's +x axis, +y points to the image's
/// left and +z up. A point (x, y, z) in the camera frame with x > 0 projects to
/// u = cx - fx * y / x, v = cy - fy * z / x, with fx = fy = (width / 2) / tan(hfov / 2),
/// cx = width / 2, cy = height / 2. Pixel (i, j) samples the ray through (u, v) = (i, j)
/// (ROS convention: integer coordinates are pixel centres); row 0 is the top of the image.
struct CameraModel {
  int width = 640;
  int height = 480;
  double horizontal_fov_rad = 1.5707;
  double clip_near_m = 0.02;
  double clip_far_m = 100.0;

  /// Throws std::invalid_argument naming the field and its value when the model is unusable
  /// (size not positive or above 16384, fov outside (0, pi), near not positive, far <= near).
  void validate() const;

  double fx() const;
  double fy() const { return fx(); }
  double cx() const { return 0.5 * width; }
  double cy() const { return 0.5 * height; }

  /// Intrinsic matrix, row-major, as sensor_msgs/CameraInfo.K wants.
  std::array<double, 9> K() const;
  /// Projection matrix [K | 0], row-major, as sensor_msgs/CameraInfo.P wants.
  std::array<double, 12> P() const;

  /// Projects a point given in the camera frame (Gazebo convention) to pixel coordinates.
  /// Returns false, leaving `uv` untouched, when the point is not in front of the camera.
  bool project(const Eigen::Vector3d& p_camera, Eigen::Vector2d* uv) const;
};

}  // namespace sim_render
