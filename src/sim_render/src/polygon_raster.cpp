#include "polygon_raster.h"

#include "span_walk.h"

#include <Eigen/LU>

#include <algorithm>
#include <atomic>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sim_render {
namespace detail {

std::uint8_t toByte(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

namespace {

// Point where segment inside -> outside crosses the plane x = near. Always computed from the
// inside end so that two triangles sharing the edge get the bit-identical point.
Eigen::Vector3d nearCrossing(const Eigen::Vector3d& inside, const Eigen::Vector3d& outside,
                             double near_m) {
  const double t = (inside.x() - near_m) / (inside.x() - outside.x());
  return inside + t * (outside - inside);
}

}  // namespace

PolygonRasterizer::PolygonRasterizer(const CameraModel& camera)
    : fx_(camera.fx()),
      fy_(camera.fy()),
      cx_(camera.cx()),
      cy_(camera.cy()),
      near_m_(camera.clip_near_m),
      far_m_(camera.clip_far_m),
      inverse_far_(static_cast<float>(1.0 / camera.clip_far_m)) {}

int PolygonRasterizer::project(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                               Eigen::Vector2d* screen, Eigen::Vector3d* plane,
                               bool* was_clipped) const {
  // Plane of the triangle: normal . p = d; d < 0 when the camera sees its front side.
  const double d = normal.dot(a);
  if (!(d < -1e-12)) return 0;
  if (a.x() < near_m_ && b.x() < near_m_ && c.x() < near_m_) return 0;
  if (a.x() > far_m_ && b.x() > far_m_ && c.x() > far_m_) return 0;

  const Eigen::Vector3d* in[3] = {&a, &b, &c};
  Eigen::Vector3d clipped[kMaxVertices];
  int count = 0;
  *was_clipped = false;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = *in[i];
    const Eigen::Vector3d& q = *in[(i + 1) % 3];
    const bool p_in = p.x() >= near_m_;
    const bool q_in = q.x() >= near_m_;
    if (p_in) clipped[count++] = p;
    if (p_in != q_in) {
      clipped[count++] = p_in ? nearCrossing(p, q, near_m_) : nearCrossing(q, p, near_m_);
      *was_clipped = true;
    }
  }
  if (count < 3) return 0;

  for (int i = 0; i < count; ++i) {
    const double inv_x = 1.0 / clipped[i].x();
    screen[i] = Eigen::Vector2d(cx_ - fx_ * clipped[i].y() * inv_x, cy_ - fy_ * clipped[i].z() * inv_x);
  }
  // 1/x on the ray through (u, v) is (n_x - n_y (u - cx) / fx - n_z (v - cy) / fy) / d.
  *plane = Eigen::Vector3d(-normal.y() / (fx_ * d), -normal.z() / (fy_ * d),
                           (normal.x() + normal.y() * cx_ / fx_ + normal.z() * cy_ / fy_) / d);
  return count;
}

Eigen::Vector3d PolygonRasterizer::attributePlane(const Eigen::Vector3d* corners,
                                                  const Eigen::Vector3d& normal,
                                                  const float value[3],
                                                  const Eigen::Vector3d& inverse_depth_plane) const {
  // s(P) = value[0] + g . (P - a) with g in the triangle's plane; on the ray through pixel
  // (u, v), P = x r with r = (1, -(u - cx) / fx, -(v - cy) / fy), so
  // s / x = g . r + (value[0] - g . a) / x: affine in (u, v).
  Eigen::Matrix3d M;
  M.row(0) = corners[1] - corners[0];
  M.row(1) = corners[2] - corners[0];
  M.row(2) = normal;
  const Eigen::Vector3d g =
      M.inverse() * Eigen::Vector3d(value[1] - value[0], value[2] - value[0], 0.0);
  const double k = value[0] - g.dot(corners[0]);
  return Eigen::Vector3d(-g.y() / fx_, -g.z() / fy_, g.x() + g.y() * cx_ / fx_ + g.z() * cy_ / fy_) +
         k * inverse_depth_plane;
}

RasterResult PolygonRasterizer::draw(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                     const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                                     const std::uint8_t rgb[3], const RasterTarget& target) const {
  Eigen::Vector2d screen[kMaxVertices];
  Eigen::Vector3d plane;
  bool clipped = false;
  const int count = project(a, b, c, normal, screen, &plane, &clipped);
  if (count == 0) return RasterResult::Culled;
  const float du = static_cast<float>(plane.x());
  const float inverse_far = inverse_far_;
  // The colour in registers: stores through `pixel` could otherwise change what `rgb`
  // points to, and it would be read again for every pixel.
  const std::uint8_t r = rgb[0], g = rgb[1], bl = rgb[2];
  forEachSpan(screen, count, target, [&](int row, int col_begin, int col_end) {
    const float base = static_cast<float>(plane.x() * col_begin + plane.y() * row + plane.z());
    float* depth = target.inverse_depth + static_cast<std::size_t>(row) * target.width;
    std::uint8_t* pixel = target.rgb8 + (static_cast<std::size_t>(row) * target.width + col_begin) * 3;
    for (int col = col_begin; col < col_end; ++col, pixel += 3) {
      const float inverse_depth = base + du * static_cast<float>(col - col_begin);
      if (inverse_depth > depth[col] && inverse_depth >= inverse_far) {
        depth[col] = inverse_depth;
        pixel[0] = r;
        pixel[1] = g;
        pixel[2] = bl;
      }
    }
  });
  return clipped ? RasterResult::DrawnClipped : RasterResult::Drawn;
}

namespace {

/// The mipmap level whose texel matches the pixel's footprint at (col, row): the larger
/// of the texture coordinates' changes to the next column and row, in level-0 texels.
int mipLevel(const Eigen::Vector3d& iz, const Eigen::Vector3d& uz, const Eigen::Vector3d& vz,
             double col, double row, const Texture& texture) {
  const double z = iz.x() * col + iz.y() * row + iz.z();
  const double u = uz.x() * col + uz.y() * row + uz.z();
  const double v = vz.x() * col + vz.y() * row + vz.z();
  if (!(z > 0)) return 0;
  const double z2 = z * z;
  const double w = texture.width(), h = texture.height();
  const double footprint = std::max(
      {std::abs((uz.x() * z - u * iz.x()) / z2) * w, std::abs((vz.x() * z - v * iz.x()) / z2) * h,
       std::abs((uz.y() * z - u * iz.y()) / z2) * w, std::abs((vz.y() * z - v * iz.y()) / z2) * h});
  if (!(footprint > 1.0)) return 0;
  const int last = static_cast<int>(texture.levels().size()) - 1;
  return std::min(last, static_cast<int>(std::log2(footprint)));
}

std::uint8_t modulate(std::uint8_t texel, int factor) {
  return static_cast<std::uint8_t>(std::min(255, (texel * factor + 128) >> 8));
}

#if defined(__SSE2__)
/// std::floor of each lane, as GCC inlines it for one float: below 2^23 in magnitude the
/// truncation, less one where it rounded up, with the sign of the value (floor(-0) = -0);
/// from 2^23 on (and NaN) the value itself.
__m128 floor4(__m128 x) {
  const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 small = _mm_cmplt_ps(_mm_and_ps(x, magnitude), _mm_set1_ps(8388608.0f));
  __m128 t = _mm_cvtepi32_ps(_mm_cvttps_epi32(x));
  t = _mm_sub_ps(t, _mm_and_ps(_mm_cmpgt_ps(t, x), _mm_set1_ps(1.0f)));
  t = _mm_or_ps(t, _mm_andnot_ps(magnitude, x));
  return _mm_or_ps(_mm_and_ps(small, t), _mm_andnot_ps(small, x));
}

/// Each lane of `values`, but at most `last` (SSE2 has no min of 32-bit integers).
__m128i lastAtMost(__m128i values, __m128i last) {
  const __m128i above = _mm_cmpgt_epi32(values, last);
  return _mm_or_si128(_mm_and_si128(above, last), _mm_andnot_si128(above, values));
}
#endif

}  // namespace

#if defined(__SSE2__)
void floorFour(const float* in, float* out) { _mm_storeu_ps(out, floor4(_mm_loadu_ps(in))); }
#endif

namespace {
std::atomic<bool> four_pixel_texturing{true};
}  // namespace

void setFourPixelTexturing(bool on) { four_pixel_texturing.store(on, std::memory_order_relaxed); }

RasterResult PolygonRasterizer::drawTextured(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                             const Eigen::Vector3d& c,
                                             const Eigen::Vector3d& normal,
                                             const TexturedCorners& corners,
                                             const RasterTarget& target) const {
  Eigen::Vector2d screen[kMaxVertices];
  Eigen::Vector3d iz;
  bool clipped = false;
  const int count = project(a, b, c, normal, screen, &iz, &clipped);
  if (count == 0) return RasterResult::Culled;
  const Eigen::Vector3d abc[3] = {a, b, c};
  const float us[3] = {corners.uv[0].x(), corners.uv[1].x(), corners.uv[2].x()};
  const float vs[3] = {corners.uv[0].y(), corners.uv[1].y(), corners.uv[2].y()};
  const Eigen::Vector3d uz = attributePlane(abc, normal, us, iz);
  const Eigen::Vector3d vz = attributePlane(abc, normal, vs, iz);
  const Texture& texture = *corners.texture;
  // Each channel's texel values as the lighting turns them (modulate()), looked up per
  // pixel instead of multiplied.
  std::uint8_t lit[3][256];
  for (int channel = 0; channel < 3 && !corners.lighting; ++channel) {
    const int factor = static_cast<int>(std::lround(corners.factor[channel] * 256.0f));
    for (int value = 0; value < 256; ++value) {
      lit[channel][value] = modulate(static_cast<std::uint8_t>(value), factor);
    }
  }
  const float inverse_far = inverse_far_;
  const float inverse_fx = static_cast<float>(1.0 / fx_), inverse_fy = static_cast<float>(1.0 / fy_);
  const float cx = static_cast<float>(cx_), cy = static_cast<float>(cy_);
  const bool four_pixel = four_pixel_texturing.load(std::memory_order_relaxed);
  forEachSpan(screen, count, target, [&](int row, int col_begin, int col_end) {
    const TextureLevel& level =
        texture.levels()[mipLevel(iz, uz, vz, 0.5 * (col_begin + col_end - 1), row, texture)];
    // The level in registers: stores through `pixel` could otherwise change it, and it would
    // be read again for every pixel.
    const int level_width = level.width, level_height = level.height;
    const std::uint8_t* const texels = level.rgb8.data();
    const float fw = static_cast<float>(level_width), fh = static_cast<float>(level_height);
    float* depth = target.inverse_depth + static_cast<std::size_t>(row) * target.width;
    std::uint8_t* pixel = target.rgb8 + (static_cast<std::size_t>(row) * target.width + col_begin) * 3;
    // Each plane at the span's first pixel in double, then stepped in float along the row
    // (as the flat-colour path steps its depth).
    const float iz0 = static_cast<float>(iz.x() * col_begin + iz.y() * row + iz.z());
    const float uz0 = static_cast<float>(uz.x() * col_begin + uz.y() * row + uz.z());
    const float vz0 = static_cast<float>(vz.x() * col_begin + vz.y() * row + vz.z());
    const float diz = static_cast<float>(iz.x()), duz = static_cast<float>(uz.x()),
                dvz = static_cast<float>(vz.x());
    const float ray_z = -(static_cast<float>(row) - cy) * inverse_fy;
    int col = col_begin;
#if defined(__SSE2__)
    // Four pixels at a time, each lane computed as the loop below computes a pixel (the same
    // operations in the same order), so that both give the same bytes.
    if (four_pixel) {
      const __m128 lanes = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f);
      const __m128 iz0v = _mm_set1_ps(iz0), uz0v = _mm_set1_ps(uz0), vz0v = _mm_set1_ps(vz0);
      const __m128 dizv = _mm_set1_ps(diz), duzv = _mm_set1_ps(duz), dvzv = _mm_set1_ps(dvz);
      const __m128 farv = _mm_set1_ps(inverse_far), one = _mm_set1_ps(1.0f);
      const __m128 fwv = _mm_set1_ps(fw), fhv = _mm_set1_ps(fh);
      const __m128i last_x = _mm_set1_epi32(level_width - 1),
                    last_y = _mm_set1_epi32(level_height - 1);
      alignas(16) int xs[4], ys[4];
      for (; col + 4 <= col_end; col += 4, pixel += 12) {
        const __m128 k = _mm_add_ps(_mm_set1_ps(static_cast<float>(col - col_begin)), lanes);
        const __m128 inverse_depth = _mm_add_ps(iz0v, _mm_mul_ps(dizv, k));
        const __m128 stored = _mm_loadu_ps(depth + col);
        const __m128 nearer = _mm_and_ps(_mm_cmpgt_ps(inverse_depth, stored),
                                         _mm_cmpge_ps(inverse_depth, farv));
        const int drawn = _mm_movemask_ps(nearer);
        if (drawn == 0) continue;
        _mm_storeu_ps(depth + col, _mm_or_ps(_mm_and_ps(nearer, inverse_depth),
                                             _mm_andnot_ps(nearer, stored)));
        const __m128 w = _mm_div_ps(one, inverse_depth);
        const __m128 u = _mm_mul_ps(_mm_add_ps(uz0v, _mm_mul_ps(duzv, k)), w);
        const __m128 v = _mm_mul_ps(_mm_add_ps(vz0v, _mm_mul_ps(dvzv, k)), w);
        _mm_store_si128(reinterpret_cast<__m128i*>(xs),
                        lastAtMost(_mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(u, floor4(u)), fwv)),
                                   last_x));
        _mm_store_si128(reinterpret_cast<__m128i*>(ys),
                        lastAtMost(_mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(v, floor4(v)), fhv)),
                                   last_y));
        if (corners.lighting) {
          alignas(16) float factors[3][4];
          litFactorsFour(*corners.lighting, w, col, inverse_fx, cx, ray_z, factors);
          for (int lane = 0; lane < 4; ++lane) {
            if (!(drawn & (1 << lane))) continue;
            const std::uint8_t* t =
                texels + (static_cast<std::size_t>(ys[lane]) * level_width + xs[lane]) * 3;
            for (int channel = 0; channel < 3; ++channel) {
              pixel[3 * lane + channel] = modulate(t[channel], factorStep(factors[channel][lane]));
            }
          }
          continue;
        }
        for (int lane = 0; lane < 4; ++lane) {
          if (!(drawn & (1 << lane))) continue;
          const std::uint8_t* t =
              texels + (static_cast<std::size_t>(ys[lane]) * level_width + xs[lane]) * 3;
          std::uint8_t* out = pixel + 3 * lane;
          out[0] = lit[0][t[0]];
          out[1] = lit[1][t[1]];
          out[2] = lit[2][t[2]];
        }
      }
    }
#endif
    for (; col < col_end; ++col, pixel += 3) {
      const float k = static_cast<float>(col - col_begin);
      const float inverse_depth = iz0 + diz * k;
      if (!(inverse_depth > depth[col] && inverse_depth >= inverse_far)) continue;
      depth[col] = inverse_depth;
      const float w = 1.0f / inverse_depth;
      const float u = (uz0 + duz * k) * w;
      const float v = (vz0 + dvz * k) * w;
      const int x = std::min(level_width - 1, static_cast<int>((u - std::floor(u)) * fw));
      const int y = std::min(level_height - 1, static_cast<int>((v - std::floor(v)) * fh));
      const std::uint8_t* t = texels + (static_cast<std::size_t>(y) * level_width + x) * 3;
      if (corners.lighting) {
        const Eigen::Vector3f factor =
            corners.lighting->colour.cwiseProduct(lightFactorAt(
                *corners.lighting, w, -(static_cast<float>(col) - cx) * inverse_fx * w, ray_z * w));
        for (int channel = 0; channel < 3; ++channel) {
          pixel[channel] = modulate(t[channel], factorStep(factor[channel]));
        }
        continue;
      }
      pixel[0] = lit[0][t[0]];
      pixel[1] = lit[1][t[1]];
      pixel[2] = lit[2][t[2]];
    }
  });
  return clipped ? RasterResult::DrawnClipped : RasterResult::Drawn;
}

}  // namespace detail
}  // namespace sim_render
