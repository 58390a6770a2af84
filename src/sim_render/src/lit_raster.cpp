#include "polygon_raster.h"

#include "span_walk.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sim_render {
namespace detail {

RasterResult PolygonRasterizer::drawLit(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                                        const PixelLighting& lighting,
                                        const RasterTarget& target) const {
  Eigen::Vector2d screen[kMaxVertices];
  Eigen::Vector3d plane;
  bool clipped = false;
  const int count = project(a, b, c, normal, screen, &plane, &clipped);
  if (count == 0) return RasterResult::Culled;
  const float du = static_cast<float>(plane.x());
  const float inverse_far = inverse_far_;
  const float inverse_fx = static_cast<float>(1.0 / fx_), inverse_fy = static_cast<float>(1.0 / fy_);
  const float cx = static_cast<float>(cx_), cy = static_cast<float>(cy_);
  const Eigen::Vector3f colour = lighting.colour;
  forEachSpan(screen, count, target, [&](int row, int col_begin, int col_end) {
    const float base = static_cast<float>(plane.x() * col_begin + plane.y() * row + plane.z());
    const float ray_z = -(static_cast<float>(row) - cy) * inverse_fy;
    float* depth = target.inverse_depth + static_cast<std::size_t>(row) * target.width;
    std::uint8_t* pixel = target.rgb8 + (static_cast<std::size_t>(row) * target.width + col_begin) * 3;
    int col = col_begin;
#if defined(__SSE2__)
    // Four pixels at a time, each lane as the loop below computes a pixel.
    const __m128 lanes = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f);
    for (; col + 4 <= col_end; col += 4, pixel += 12) {
      const __m128 k = _mm_add_ps(_mm_set1_ps(static_cast<float>(col - col_begin)), lanes);
      const __m128 inverse_depth = _mm_add_ps(_mm_set1_ps(base), _mm_mul_ps(_mm_set1_ps(du), k));
      const __m128 stored = _mm_loadu_ps(depth + col);
      const __m128 nearer = _mm_and_ps(_mm_cmpgt_ps(inverse_depth, stored),
                                       _mm_cmpge_ps(inverse_depth, _mm_set1_ps(inverse_far)));
      const int drawn = _mm_movemask_ps(nearer);
      if (drawn == 0) continue;
      _mm_storeu_ps(depth + col, _mm_or_ps(_mm_and_ps(nearer, inverse_depth),
                                           _mm_andnot_ps(nearer, stored)));
      alignas(16) float factors[3][4];
      litFactorsFour(lighting, _mm_div_ps(_mm_set1_ps(1.0f), inverse_depth), col, inverse_fx, cx,
                     ray_z, factors);
      for (int lane = 0; lane < 4; ++lane) {
        if (!(drawn & (1 << lane))) continue;
        for (int channel = 0; channel < 3; ++channel) {
          pixel[3 * lane + channel] = toByte(factors[channel][lane]);
        }
      }
    }
#endif
    for (; col < col_end; ++col, pixel += 3) {
      const float inverse_depth = base + du * static_cast<float>(col - col_begin);
      if (!(inverse_depth > depth[col] && inverse_depth >= inverse_far)) continue;
      depth[col] = inverse_depth;
      const float x = 1.0f / inverse_depth;
      const Eigen::Vector3f light = lightFactorAt(
          lighting, x, -(static_cast<float>(col) - cx) * inverse_fx * x, ray_z * x);
      pixel[0] = toByte(colour.x() * light.x());
      pixel[1] = toByte(colour.y() * light.y());
      pixel[2] = toByte(colour.z() * light.z());
    }
  });
  return clipped ? RasterResult::DrawnClipped : RasterResult::Drawn;
}

}  // namespace detail
}  // namespace sim_render
