#ifndef BULLET_SIM_TEST_ROUND_TRACK_H
#define BULLET_SIM_TEST_ROUND_TRACK_H

#include <vector>

#include <Eigen/Core>

namespace bullet_sim_test {

/// A round-track wall as DESIGN.md lists it: centre x, y (m), yaw (rad), length (m).
struct Wall {
  double x, y, yaw, length;
};
constexpr double kWallThicknessM = 0.015;
constexpr double kWallHeightM = 0.5;

/// The 21 walls of DESIGN.md's table, in its order.
const std::vector<Wall>& roundTrackWalls();

/// Distance along a horizontal ray from `origin` (x, y) at world heading
/// `heading_rad` to the first round-track wall, computed in 2D from the wall
/// table of DESIGN.md (walls 0.015 m thick, length along their local y);
/// +inf when no wall is within `max_range_m`.
double wallDistance(const Eigen::Vector2d& origin, double heading_rad, double max_range_m);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_ROUND_TRACK_H
