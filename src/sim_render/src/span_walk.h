// Internal: the pixel spans a convex screen polygon covers, row by row.
#pragma once

#include "polygon_raster.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace sim_render {
namespace detail {

// Edge i -> j as e(u, v) = A u + B v + C. Swapping i and j negates A, B and C exactly, which
// makes the span limits of neighbouring triangles bit-identical.
struct Edge {
  double a, b, c, inv_a;
};

inline Edge makeEdge(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double orientation) {
  Edge e;
  e.a = orientation * (p.y() - q.y());
  e.b = orientation * (q.x() - p.x());
  e.c = orientation * (p.x() * q.y() - q.x() * p.y());
  e.inv_a = e.a != 0.0 ? 1.0 / e.a : 0.0;
  return e;
}

/// Calls write(row, col_begin, col_end) for each row of the convex polygon `screen`
/// (`count` corners) inside the target, with the columns whose pixels it owns.
template <class WriteSpan>
void forEachSpan(const Eigen::Vector2d* screen, int count, const RasterTarget& target,
                 WriteSpan&& write) {
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
  Edge edges[4];
  for (int i = 0; i < count; ++i) edges[i] = makeEdge(screen[i], screen[(i + 1) % count], orientation);

  const int row_begin = static_cast<int>(std::ceil(std::max(v_min, -1.0)));
  const int row_end = static_cast<int>(std::floor(std::min(v_max, static_cast<double>(target.height))));
  const double width = target.width;
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
    write(row, col_begin, col_end);
  }
}

}  // namespace detail
}  // namespace sim_render
