// Internal: a frame's point, spot and directional lights, and which of them reach a shape
// and a triangle.
#pragma once

#include "pixel_lighting.h"
#include "sim_render/scene.h"

#include <Eigen/Geometry>

#include <vector>

namespace sim_render {
namespace detail {

/// The scene's lights (other than the sun) for one frame. prepare() once per frame, then
/// selectForShape() per shape and onTriangle() per triangle of that shape.
class FrameLights {
 public:
  /// Takes `lighting.lights`, point and spot lights moved into the camera frame; lights
  /// with a non-finite or zero value where one is needed (direction, range) are left out.
  void prepare(const Lighting& lighting, const Eigen::Isometry3d& T_camera_world);

  /// Keeps the point and spot lights that may reach the shape whose bounding sphere is
  /// centred at `centre` (camera frame).
  void selectForShape(const Eigen::Vector3d& centre, double radius_m);

  /// The directional lights' sum for a surface of world-frame unit normal `normal`.
  Eigen::Vector3f directionalTerm(const Eigen::Vector3d& normal) const;

  /// The per-pixel lighting of a camera-frame triangle of the selected shape (outward unit
  /// normal `normal`), or null when no point or spot light reaches it: its pixels then take
  /// `base` alone. Valid until the next call.
  const PixelLighting* onTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                                  const Eigen::Vector3f& base, const Eigen::Vector3f& colour);

 private:
  /// A point or spot light in the camera frame: `pixel` as the rasterizer takes it, and
  /// what a shape's or triangle's reach is tested with.
  struct CameraLight {
    PixelLight pixel;
    Eigen::Vector3d position, axis;
    double range_m;
    double outer_half_rad;  ///< spot only, else pi
  };
  struct DirectionalLight {
    Eigen::Vector3d to_light;
    Eigen::Vector3f diffuse;
  };

  static CameraLight cameraLight(const LocalLight& light, const Eigen::Isometry3d& T_camera_world);
  /// Whether `light` may light part of the sphere around `centre`: within its range and,
  /// for a spot light, inside its outer cone.
  static bool reaches(const CameraLight& light, const Eigen::Vector3d& centre, double radius_m);

  std::vector<CameraLight> camera_lights_;
  std::vector<DirectionalLight> directional_lights_;
  std::vector<const CameraLight*> shape_lights_;
  std::vector<PixelLight> triangle_lights_;
  PixelLighting pixel_lighting_;
};

}  // namespace detail
}  // namespace sim_render
