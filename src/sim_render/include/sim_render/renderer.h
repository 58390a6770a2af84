/// @file renderer.h
/// @brief Z-buffered CPU rasterizer that renders a Scene through a CameraModel.
#pragma once

#include "sim_render/camera_model.h"
#include "sim_render/scene.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace sim_render {

/// Counters of the last frame, for tests and benchmarks.
struct RenderStats {
  std::size_t shapes_drawn = 0;     ///< shapes not rejected by the frustum test
  std::size_t triangles_drawn = 0;  ///< triangles that reached the rasterizer
  std::size_t triangles_clipped = 0;  ///< of those, cut by the near plane
};

/// Renders scenes with one camera model. Holds its depth buffer and scratch space, so a
/// frame allocates nothing once the output vector has its size. Deterministic: the same
/// scene and pose give the same bytes. Not thread-safe; use one Renderer per thread.
namespace detail {
class FrameLights;
}  // namespace detail

class Renderer {
 public:
  /// Validates the camera (std::invalid_argument naming the bad value).
  explicit Renderer(const CameraModel& camera);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  const CameraModel& camera() const { return camera_; }

  /// Draws `scene` seen from a camera at `T_world_camera` (Gazebo convention, see
  /// CameraModel) into `out_rgb8`, resized to width * height * 3, row-major, row 0 on top.
  void render(const Scene& scene, const Eigen::Isometry3d& T_world_camera,
              std::vector<std::uint8_t>& out_rgb8);

  /// Depth along the camera's +x axis at pixel (col, row) of the last frame, in metres;
  /// +infinity where nothing was drawn or out of the image.
  double depthAt(int col, int row) const;

  /// Depth along the camera's +x axis (the optical axis) of every pixel of the last frame,
  /// in metres, row-major, row 0 on top: the frame's depth buffer, no extra pass. NaN where
  /// nothing was drawn (nothing within the far clip distance) and where the depth is not
  /// strictly between `above_m` and `below_m` (a depth camera's cutoffs; by default any
  /// depth passes). Resizes `depth_m`.
  void depthImage(std::vector<float>* depth_m, float above_m = 0.0f,
                  float below_m = std::numeric_limits<float>::infinity()) const;

  const RenderStats& lastStats() const { return stats_; }

 private:
  CameraModel camera_;
  std::vector<float> inverse_depth_;
  std::vector<Eigen::Vector3d> camera_vertices_;
  std::vector<std::pair<double, std::size_t>> draw_order_;  ///< (sort key, shape index)
  RenderStats stats_;
  std::unique_ptr<detail::FrameLights> lights_;  ///< the lights of the frame being drawn
};

}  // namespace sim_render
