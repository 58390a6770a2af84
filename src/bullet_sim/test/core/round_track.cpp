#include "round_track.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bullet_sim_test {
namespace {

// DESIGN.md, "World roundTrack": centre x, y, yaw, length (m).
const std::vector<Wall> kWalls = {
    {1.53496, 2.894504, 0.736056, 1.0}, {2.04294, 2.386858, 0.881268, 0.5},
    {3.72582, 2.23758, 1.57177, 3.0},   {0.196982, 3.258921, 1.57467, 2.0},
    {5.21431, 0.73692, -0.000378, 3.0}, {3.8664, -2.46629, -1.1525, 0.5},
    {5.13135, -0.99504, -0.334721, 0.5}, {4.92558, -1.45102, -0.501603, 0.5},
    {4.2862, -2.20397, -0.858577, 0.5}, {3.41064, -2.6531, 1.9485, 0.5},
    {-0.80941, 0.25461, 0, 6.0},        {4.63833, -1.85451, 2.40733, 0.5},
    {1.1918, -2.74499, 1.5735, 4.0},    {0.54193, 0.34703, 0, 3.8},
    {0.87641, 1.88745, 0.736056, 1.0},  {1.4037, 1.35442, 0.881268, 0.5},
    {2.78265, 1.19568, 1.57177, 2.4},   {3.98336, 0.09495, -0.000378, 2.2},
    {1.89949, -1.53786, 1.5735, 2.7},   {3.43608, -1.41841, 2.08925, 0.5},
    {3.79555, -1.15857, -0.858577, 0.5}};

/// Slab test of a ray against an axis-aligned rectangle centred at 0.
double rayRectangle(const Eigen::Vector2d& o, const Eigen::Vector2d& d, double half_x,
                    double half_y) {
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  const double half[2] = {half_x, half_y};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::fabs(d[axis]) < 1e-12) {
      if (std::fabs(o[axis]) > half[axis]) return std::numeric_limits<double>::infinity();
      continue;
    }
    double t0 = (-half[axis] - o[axis]) / d[axis];
    double t1 = (half[axis] - o[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far || t_far < 0) return std::numeric_limits<double>::infinity();
  return t_near >= 0 ? t_near : 0.0;
}

}  // namespace

const std::vector<Wall>& roundTrackWalls() { return kWalls; }

double wallDistance(const Eigen::Vector2d& origin, double heading_rad, double max_range_m) {
  const Eigen::Vector2d dir(std::cos(heading_rad), std::sin(heading_rad));
  double best = std::numeric_limits<double>::infinity();
  for (const Wall& w : kWalls) {
    // Into the wall's frame: rotate by -yaw about its centre.
    const double c = std::cos(w.yaw), s = std::sin(w.yaw);
    const Eigen::Vector2d rel = origin - Eigen::Vector2d(w.x, w.y);
    const Eigen::Vector2d o(c * rel.x() + s * rel.y(), -s * rel.x() + c * rel.y());
    const Eigen::Vector2d d(c * dir.x() + s * dir.y(), -s * dir.x() + c * dir.y());
    best = std::min(best, rayRectangle(o, d, kWallThicknessM / 2, w.length / 2));
  }
  return best <= max_range_m ? best : std::numeric_limits<double>::infinity();
}

}  // namespace bullet_sim_test
