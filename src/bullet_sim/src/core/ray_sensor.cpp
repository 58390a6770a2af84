#include "ray_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bullet_convert.h"

namespace bullet_sim {

void castScan(const btCollisionWorld& world, const Eigen::Isometry3d& T_world_sensor,
              const RaySpec& spec, std::mt19937_64* rng, LaserScanData* scan) {
  scan->frame_id = spec.frame_id;
  scan->angle_min = spec.min_angle_rad;
  scan->angle_max = spec.max_angle_rad;
  scan->angle_increment =
      spec.samples > 1 ? (spec.max_angle_rad - spec.min_angle_rad) / (spec.samples - 1) : 0.0;
  scan->time_increment = 0;
  scan->scan_time = spec.update_rate_hz > 0 ? 1.0 / spec.update_rate_hz : 0.0;
  scan->range_min = spec.range_min_m;
  scan->range_max = spec.range_max_m;
  scan->ranges.assign(spec.samples, std::numeric_limits<float>::infinity());
  scan->intensities.assign(spec.samples, 0.0f);

  std::normal_distribution<double> noise(spec.noise_mean_m, spec.noise_stddev_m);
  const bool noisy = spec.noise_stddev_m > 0 || spec.noise_mean_m != 0;
  const Eigen::Vector3d origin = T_world_sensor.translation();
  const Eigen::Matrix3d R = T_world_sensor.linear();
  const double span = spec.range_max_m - spec.range_min_m;
  for (int i = 0; i < spec.samples; ++i) {
    const double angle = spec.min_angle_rad + i * scan->angle_increment;
    const Eigen::Vector3d dir = R * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    const btVector3 from = toBt(origin + dir * spec.range_min_m);
    const btVector3 to = toBt(origin + dir * spec.range_max_m);
    btCollisionWorld::ClosestRayResultCallback hit(from, to);
    world.rayTest(from, to, hit);
    if (!hit.hasHit()) continue;
    double range = spec.range_min_m + hit.m_closestHitFraction * span;
    if (noisy) range += noise(*rng);
    if (spec.range_resolution_m > 0) {
      range = std::round(range / spec.range_resolution_m) * spec.range_resolution_m;
    }
    scan->ranges[i] = static_cast<float>(std::clamp(range, spec.range_min_m, spec.range_max_m));
  }
}

}  // namespace bullet_sim
