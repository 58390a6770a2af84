#include "polygon_raster.h"

#include <algorithm>
#include <cmath>

namespace sim_render {
namespace detail {
namespace {

// Point where segment inside -> outside crosses the plane x = near. Always computed from the
// inside end so that two triangles sharing the edge get the bit-identical point.
Eigen::Vector3d nearCrossing(const Eigen::Vector3d& inside, const Eigen::Vector3d& outside,
                             double near_m) {
  const double t = (inside.x() - near_m) / (inside.x() - outside.x());
  return inside + t * (outside - inside);
}

// Edge i -> j as e(u, v) = A u + B v + C. Swapping i and j negates A, B and C exactly, which
// makes the span limits of neighbouring triangles bit-identical.
struct Edge {
  double a, b, c, inv_a;
};

Edge makeEdge(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double orientation) {
  Edge e;
  e.a = orientation * (p.y() - q.y());
  e.b = orientation * (q.x() - p.x());
  e.c = orientation * (p.x() * q.y() - q.x() * p.y());
  e.inv_a = e.a != 0.0 ? 1.0 / e.a : 0.0;
  return e;
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

RasterResult PolygonRasterizer::draw(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                     const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                                     const std::uint8_t rgb[3], const RasterTarget& target) const {
  // Plane of the triangle: normal . p = d; d < 0 when the camera sees its front side.
  const double d = normal.dot(a);
  if (!(d < -1e-12)) return RasterResult::Culled;
  if (a.x() < near_m_ && b.x() < near_m_ && c.x() < near_m_) return RasterResult::Culled;
  if (a.x() > far_m_ && b.x() > far_m_ && c.x() > far_m_) return RasterResult::Culled;

  const Eigen::Vector3d* in[3] = {&a, &b, &c};
  Eigen::Vector3d clipped[kMaxVertices];
  int count = 0;
  bool was_clipped = false;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& p = *in[i];
    const Eigen::Vector3d& q = *in[(i + 1) % 3];
    const bool p_in = p.x() >= near_m_;
    const bool q_in = q.x() >= near_m_;
    if (p_in) clipped[count++] = p;
    if (p_in != q_in) {
      clipped[count++] = p_in ? nearCrossing(p, q, near_m_) : nearCrossing(q, p, near_m_);
      was_clipped = true;
    }
  }
  if (count < 3) return RasterResult::Culled;

  Eigen::Vector2d screen[kMaxVertices];
  for (int i = 0; i < count; ++i) {
    const double inv_x = 1.0 / clipped[i].x();
    screen[i] = Eigen::Vector2d(cx_ - fx_ * clipped[i].y() * inv_x, cy_ - fy_ * clipped[i].z() * inv_x);
  }
  // 1/x on the ray through (u, v) is (n_x - n_y (u - cx) / fx - n_z (v - cy) / fy) / d.
  const Eigen::Vector3d plane(-normal.y() / (fx_ * d), -normal.z() / (fy_ * d),
                              (normal.x() + normal.y() * cx_ / fx_ + normal.z() * cy_ / fy_) / d);
  fill(screen, count, plane, rgb, target);
  return was_clipped ? RasterResult::DrawnClipped : RasterResult::Drawn;
}

void PolygonRasterizer::fill(const Eigen::Vector2d* screen, int count,
                             const Eigen::Vector3d& inverse_depth_plane, const std::uint8_t rgb[3],
                             const RasterTarget& target) const {
  double twice_area = 0.0;
  double v_min = screen[0].y(), v_max = screen[0].y();
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d& p = screen[i];
    const Eigen::Vector2d& q = screen[(i + 1) % count];
    twice_area += p.x() * q.y() - q.x() * p.y();
    v_min = std::min(v_min, p.y());
    v_max = std::max(v_max, p.y());
  }
  if (twice_area == 0.0 || !std::isfinite(twice_area)) return;
  const double orientation = twice_area > 0.0 ? 1.0 : -1.0;
  Edge edges[kMaxVertices];
  for (int i = 0; i < count; ++i) edges[i] = makeEdge(screen[i], screen[(i + 1) % count], orientation);

  const int row_begin = static_cast<int>(std::ceil(std::max(v_min, -1.0)));
  const int row_end = static_cast<int>(std::floor(std::min(v_max, static_cast<double>(target.height))));
  const double width = target.width;
  const float du = static_cast<float>(inverse_depth_plane.x());
  for (int row = std::max(row_begin, 0); row <= std::min(row_end, target.height - 1); ++row) {
    double lo = 0.0, hi = width;
    bool empty = false;
    for (int k = 0; k < count && !empty; ++k) {
      const Edge& e = edges[k];
      const double s = e.b * row + e.c;
      if (e.a > 0.0) {
        lo = std::max(lo, -s * e.inv_a);       // inside: u >= limit (limit included)
      } else if (e.a < 0.0) {
        hi = std::min(hi, -s * e.inv_a);       // inside: u < limit (limit excluded)
      } else {
        empty = s < 0.0 || (s == 0.0 && e.b < 0.0);
      }
    }
    if (empty || !(lo < hi)) continue;
    const int col_begin = static_cast<int>(std::ceil(lo));
    const int col_end = static_cast<int>(std::ceil(hi));
    if (col_begin >= col_end) continue;

    const float base = static_cast<float>(inverse_depth_plane.x() * col_begin +
                                          inverse_depth_plane.y() * row + inverse_depth_plane.z());
    float* depth = target.inverse_depth + static_cast<std::size_t>(row) * target.width;
    std::uint8_t* pixel = target.rgb8 + (static_cast<std::size_t>(row) * target.width + col_begin) * 3;
    const float inverse_far = inverse_far_;
    // The colour in registers: stores through `pixel` could otherwise change what `rgb`
    // points to, and it would be read again for every pixel.
    const std::uint8_t r = rgb[0], g = rgb[1], b = rgb[2];
    for (int col = col_begin; col < col_end; ++col, pixel += 3) {
      const float inverse_depth = base + du * static_cast<float>(col - col_begin);
      if (inverse_depth > depth[col] && inverse_depth >= inverse_far) {
        depth[col] = inverse_depth;
        pixel[0] = r;
        pixel[1] = g;
        pixel[2] = b;
      }
    }
  }
}

}  // namespace detail
}  // namespace sim_render
