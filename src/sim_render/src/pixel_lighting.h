// Internal: the light factor of one pixel under point and spot lights.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

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
/// plus each light's term, in float (as OGRE's shaders compute it).
inline Eigen::Vector3f lightFactorAt(const PixelLighting& lighting, float x, float y, float z) {
  float r = lighting.base.x(), g = lighting.base.y(), b = lighting.base.z();
  for (int i = 0; i < lighting.count; ++i) {
    const PixelLight& l = lighting.lights[i];
    const float dx = l.x - x, dy = l.y - y, dz = l.z - z;
    const float d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 <= l.range_squared) || d2 <= 0.0f) continue;
    const float d = std::sqrt(d2);
    const float inverse_d = 1.0f / d;
    // n . L: the light's height above the triangle's plane over its distance.
    float k = l.plane_distance * inverse_d /
              std::max(l.constant + l.linear * d + l.quadratic * d2, 1e-6f);
    if (l.spot) {
      const float rho = -(l.axis_x * dx + l.axis_y * dy + l.axis_z * dz) * inverse_d;
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

}  // namespace detail
}  // namespace sim_render
