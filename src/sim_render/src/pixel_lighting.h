// Internal: the light factor of one pixel under point and spot lights.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sim_render {
namespace detail {

/// A point or spot light in the camera frame, as one triangle's pixels take it (see
/// sim_render::LocalLight for the terms).
struct PixelLight {
  float x, y, z;              ///< position
  float axis_x, axis_y, axis_z;  ///< spot: unit direction the light travels
  float r, g, b;              ///< diffuse
  float range_squared;
  float constant, linear, quadratic;
  float cos_outer_half;       ///< spot: cos(outer / 2)
  float inverse_cone;         ///< spot: 1 / (cos(inner / 2) - cos(outer / 2)), large for a hard edge
  float falloff;
  bool spot;
  float plane_distance;       ///< distance of the light from the triangle's plane, > 0
};

/// The per-pixel lighting of one triangle: the lights that can reach it, and the factor
/// the lights' terms are added to (ambient, sun, directional lights).
struct PixelLighting {
  const PixelLight* lights = nullptr;
  int count = 0;
  Eigen::Vector3f base{0.0f, 0.0f, 0.0f};
  Eigen::Vector3f colour{1.0f, 1.0f, 1.0f};  ///< the surface's colour (tint of a texture)
};

/// The light factor at the camera-frame point (x, y, z) of a triangle: `lighting.base`
/// plus each light's term, in float (as OGRE's shaders compute it). lightFactorFour()
/// does the same operations in the same order, four points at a time.
inline Eigen::Vector3f lightFactorAt(const PixelLighting& lighting, float x, float y, float z) {
  float r = lighting.base.x(), g = lighting.base.y(), b = lighting.base.z();
  for (int i = 0; i < lighting.count; ++i) {
    const PixelLight& l = lighting.lights[i];
    const float dx = l.x - x, dy = l.y - y, dz = l.z - z;
    const float d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 <= l.range_squared && d2 > 0.0f)) continue;
    const float d = std::sqrt(d2);
    // n . L (the light's height above the triangle's plane over d) times the attenuation.
    float k = l.plane_distance / (d * std::max(l.constant + l.linear * d + l.quadratic * d2, 1e-6f));
    if (l.spot) {
      const float rho = -(l.axis_x * dx + l.axis_y * dy + l.axis_z * dz) / d;
      float e = (rho - l.cos_outer_half) * l.inverse_cone;
      if (!(e > 0.0f)) continue;
      e = std::min(e, 1.0f);
      if (l.falloff != 1.0f) e = std::pow(e, l.falloff);
      k *= e;
    }
    r += l.r * k;
    g += l.g * k;
    b += l.b * k;
  }
  return Eigen::Vector3f(r, g, b);
}

#if defined(__SSE2__)
/// lightFactorAt() of the four points whose coordinates are the lanes of x, y and z.
inline void lightFactorFour(const PixelLighting& lighting, __m128 x, __m128 y, __m128 z,
                            __m128* r, __m128* g, __m128* b) {
  __m128 sr = _mm_set1_ps(lighting.base.x()), sg = _mm_set1_ps(lighting.base.y()),
         sb = _mm_set1_ps(lighting.base.z());
  const __m128 zero = _mm_setzero_ps();
  for (int i = 0; i < lighting.count; ++i) {
    const PixelLight& l = lighting.lights[i];
    const __m128 dx = _mm_sub_ps(_mm_set1_ps(l.x), x), dy = _mm_sub_ps(_mm_set1_ps(l.y), y),
                 dz = _mm_sub_ps(_mm_set1_ps(l.z), z);
    const __m128 d2 =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    __m128 in = _mm_and_ps(_mm_cmple_ps(d2, _mm_set1_ps(l.range_squared)), _mm_cmpgt_ps(d2, zero));
    if (_mm_movemask_ps(in) == 0) continue;
    const __m128 d = _mm_sqrt_ps(d2);
    const __m128 denominator = _mm_max_ps(
        _mm_add_ps(_mm_add_ps(_mm_set1_ps(l.constant), _mm_mul_ps(_mm_set1_ps(l.linear), d)),
                   _mm_mul_ps(_mm_set1_ps(l.quadratic), d2)),
        _mm_set1_ps(1e-6f));
    __m128 k = _mm_div_ps(_mm_set1_ps(l.plane_distance), _mm_mul_ps(d, denominator));
    if (l.spot) {
      const __m128 along = _mm_add_ps(
          _mm_add_ps(_mm_mul_ps(_mm_set1_ps(l.axis_x), dx), _mm_mul_ps(_mm_set1_ps(l.axis_y), dy)),
          _mm_mul_ps(_mm_set1_ps(l.axis_z), dz));
      const __m128 rho = _mm_div_ps(_mm_sub_ps(zero, along), d);
      __m128 e = _mm_mul_ps(_mm_sub_ps(rho, _mm_set1_ps(l.cos_outer_half)),
                            _mm_set1_ps(l.inverse_cone));
      in = _mm_and_ps(in, _mm_cmpgt_ps(e, zero));
      e = _mm_min_ps(e, _mm_set1_ps(1.0f));
      if (l.falloff != 1.0f) {
        alignas(16) float lanes[4];
        _mm_store_ps(lanes, e);
        for (float& lane : lanes) lane = lane > 0.0f ? std::pow(lane, l.falloff) : 0.0f;
        e = _mm_load_ps(lanes);
      }
      k = _mm_mul_ps(k, e);
    }
    k = _mm_and_ps(in, k);
    sr = _mm_add_ps(sr, _mm_mul_ps(_mm_set1_ps(l.r), k));
    sg = _mm_add_ps(sg, _mm_mul_ps(_mm_set1_ps(l.g), k));
    sb = _mm_add_ps(sb, _mm_mul_ps(_mm_set1_ps(l.b), k));
  }
  *r = sr;
  *g = sg;
  *b = sb;
}
#endif

/// A light factor (colour times light) in 1/256 steps, as modulate() takes it.
inline int factorStep(float factor) {
  return static_cast<int>(std::min(std::max(factor, 0.0f), 256.0f) * 256.0f + 0.5f);
}

#if defined(__SSE2__)
/// The colour-times-light factors of the four pixels from column `col` of a span (lanes
/// at depth x along the optical axis; `ray_z` the row's ray), per channel.
inline void litFactorsFour(const PixelLighting& lighting, __m128 x, int col, float inverse_fx, float cx,
                    float ray_z, float factors[3][4]) {
  const __m128 columns = _mm_add_ps(_mm_set1_ps(static_cast<float>(col)), _mm_set_ps(3, 2, 1, 0));
  const __m128 y = _mm_mul_ps(
      _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(0.0f), _mm_sub_ps(columns, _mm_set1_ps(cx))),
                 _mm_set1_ps(inverse_fx)),
      x);
  const __m128 z = _mm_mul_ps(_mm_set1_ps(ray_z), x);
  __m128 r, g, b;
  lightFactorFour(lighting, x, y, z, &r, &g, &b);
  _mm_store_ps(factors[0], _mm_mul_ps(r, _mm_set1_ps(lighting.colour.x())));
  _mm_store_ps(factors[1], _mm_mul_ps(g, _mm_set1_ps(lighting.colour.y())));
  _mm_store_ps(factors[2], _mm_mul_ps(b, _mm_set1_ps(lighting.colour.z())));
}
#endif

}  // namespace detail
}  // namespace sim_render
