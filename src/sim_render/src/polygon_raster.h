// Internal: near-plane clipping and scanline rasterization of one camera-frame triangle.
#pragma once

#include "pixel_lighting.h"
#include "sim_render/camera_model.h"
#include "sim_render/texture.h"

#include <Eigen/Core>

#include <cstdint>

namespace sim_render {
namespace detail {

/// Colour and inverse-depth buffers of one frame, row-major, row 0 on top.
struct RasterTarget {
  int width = 0;
  int height = 0;
  float* inverse_depth = nullptr;  ///< 1 / depth, 0 = empty
  std::uint8_t* rgb8 = nullptr;
};

/// A colour channel in [0, 1] as a byte, clamped and rounded.
std::uint8_t toByte(float value);

enum class RasterResult { Culled, Drawn, DrawnClipped };

#if defined(__SSE2__)
/// std::floor of in[0..3] into out[0..3], four at a time as the textured spans take it
/// (SSE2; the same bits as std::floor for every float).
void floorFour(const float* in, float* out);
#endif
/// Whether textured spans take four pixels at a time where the processor can (the
/// default) or one at a time; both give the same bytes. For tests that compare them.
void setFourPixelTexturing(bool on);

/// A texture as one triangle is painted with it: the coordinates of its corners and the
/// light's factor per channel (colour times lighting; 1 leaves the texel as it is), or,
/// with `lighting`, the factor worked out per pixel.
struct TexturedCorners {
  const Texture* texture = nullptr;
  Eigen::Vector2f uv[3];
  Eigen::Vector3f factor{1.0f, 1.0f, 1.0f};
  const PixelLighting* lighting = nullptr;
};

/// Draws triangles given in the camera frame (Gazebo convention) with one flat colour.
/// Depth is tested and stored as 1 / x (x = distance along the optical axis), which is an
/// affine function of the pixel coordinates over a planar polygon, hence perspective-correct.
/// Pixels are owned by exactly one of two triangles sharing an edge (consistent tie rule).
class PolygonRasterizer {
 public:
  explicit PolygonRasterizer(const CameraModel& camera);

  /// `normal` is the triangle's outward unit normal in the camera frame; back faces (and
  /// faces seen edge-on) are culled.
  RasterResult draw(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& normal, const std::uint8_t rgb[3],
                    const RasterTarget& target) const;

  /// As draw(), each pixel's colour `lighting.colour` times its light factor worked out
  /// at the pixel's point of the triangle.
  RasterResult drawLit(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& normal, const PixelLighting& lighting,
                       const RasterTarget& target) const;

  /// As draw(), each pixel the texel under it (perspective-correct: u / x and v / x are
  /// affine in the pixel coordinates, as 1 / x is) times `corners.factor`.
  RasterResult drawTextured(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                            const TexturedCorners& corners, const RasterTarget& target) const;

 private:
  static constexpr int kMaxVertices = 4;  // a triangle cut by one plane

  /// The triangle clipped by the near plane and projected: `screen` gets its corners.
  /// Returns the corner count (0: nothing to draw) and sets `plane` to 1/x over the pixels.
  int project(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
              const Eigen::Vector3d& normal, Eigen::Vector2d* screen, Eigen::Vector3d* plane,
              bool* clipped) const;
  /// The plane over the pixels of (attribute / x) for an attribute affine over the
  /// triangle's plane, taking `value[i]` at corner i.
  Eigen::Vector3d attributePlane(const Eigen::Vector3d* corners, const Eigen::Vector3d& normal,
                                 const float value[3],
                                 const Eigen::Vector3d& inverse_depth_plane) const;

  double fx_, fy_, cx_, cy_;
  double near_m_, far_m_;
  float inverse_far_;
};

}  // namespace detail
}  // namespace sim_render
