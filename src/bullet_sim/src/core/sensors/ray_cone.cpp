#include "sensors/ray_cone.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/bullet_convert.h"
#include "sensors/ray_sensor.h"

namespace bullet_sim {
namespace {

double spaced(int index, int samples, double min_rad, double max_rad) {
  return samples > 1 ? min_rad + index * (max_rad - min_rad) / (samples - 1) : 0.0;
}

/// Gazebo's GaussianKernel(0, sigma): none when sigma is 0.
double noise(std::mt19937_64* rng, double sigma) {
  if (sigma <= 0) return 0;
  return std::normal_distribution<double>(0.0, sigma)(*rng);
}

/// The two rays around reading `index` of `count` readings over `rays` rays, and how far
/// between them (0..1) it lies.
struct Between {
  int a, b;
  double fraction;
};
Between between(int index, int count, int rays) {
  const double at = count == 1 ? 0.0 : static_cast<double>(index) * (rays - 1) / (count - 1);
  const int a = static_cast<int>(std::floor(at));
  return {a, std::min(a + 1, rays - 1), at - std::floor(at)};
}

}  // namespace

double coneYaw(const RayConeSpec& cone, int i) {
  return spaced(i, cone.samples, cone.min_angle_rad, cone.max_angle_rad);
}

double conePitch(const RayConeSpec& cone, int j) {
  return spaced(j, cone.vertical_samples, cone.vertical_min_angle_rad,
                cone.vertical_max_angle_rad);
}

Eigen::Vector3d coneDirection(double yaw_rad, double pitch_rad) {
  return Eigen::Vector3d(std::cos(pitch_rad) * std::cos(yaw_rad),
                         std::cos(pitch_rad) * std::sin(yaw_rad), std::sin(pitch_rad));
}

std::vector<double> castRayCone(btCollisionWorld& world, const Eigen::Isometry3d& T_world_sensor,
                                const RayConeSpec& cone) {
  std::vector<double> ranges;
  ranges.reserve(static_cast<size_t>(cone.samples) * cone.vertical_samples);
  const double span = cone.range_max_m - cone.range_min_m;
  for (int j = 0; j < cone.vertical_samples; ++j) {
    for (int i = 0; i < cone.samples; ++i) {
      const Eigen::Vector3d dir = T_world_sensor.linear() * coneDirection(coneYaw(cone, i), conePitch(cone, j));
      const Eigen::Vector3d origin = T_world_sensor.translation();
      const double fraction = firstHitFraction(world, toBt(origin + dir * cone.range_min_m),
                                               toBt(origin + dir * cone.range_max_m));
      ranges.push_back(cone.range_min_m + fraction * span);
    }
  }
  return ranges;
}

RangeData rangeReading(const RangeSpec& spec, const std::vector<double>& ranges,
                       std::mt19937_64* rng) {
  RangeData r;
  r.frame_id = spec.frame_id;
  r.infrared = spec.infrared;
  r.field_of_view = static_cast<float>(spec.fov_rad);
  r.min_range = static_cast<float>(spec.rays.range_min_m);
  r.max_range = static_cast<float>(spec.rays.range_max_m);
  double nearest = std::numeric_limits<float>::max();
  for (double range : ranges) nearest = std::min(nearest, range);
  if (nearest < r.max_range) {
    nearest = std::min(nearest + noise(rng, spec.gaussian_noise), spec.rays.range_max_m);
  }
  r.range = static_cast<float>(nearest);
  return r;
}

BlockLaserCloudData blockLaserCloud(const BlockLaserSpec& spec, const std::vector<double>& ranges,
                               std::mt19937_64* rng) {
  const RayConeSpec& cone = spec.rays;
  const int rays = cone.samples, vertical_rays = cone.vertical_samples;
  const int count = static_cast<int>(cone.samples * cone.resolution);
  const int vertical_count = static_cast<int>(cone.vertical_samples * cone.vertical_resolution);
  BlockLaserCloudData cloud;
  cloud.frame_id = spec.frame_id;
  cloud.points.reserve(static_cast<size_t>(std::max(0, count * vertical_count)));
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int j = 0; j < vertical_count; ++j) {
    const Between v = between(j, vertical_count, vertical_rays);
    for (int i = 0; i < count; ++i) {
      const Between h = between(i, count, rays);
      const auto at = [&](int hi, int vi) { return ranges[static_cast<size_t>(vi) * rays + hi]; };
      double r = (1 - v.fraction) * ((1 - h.fraction) * at(h.a, v.a) + h.fraction * at(h.b, v.a)) +
                 v.fraction * ((1 - h.fraction) * at(h.a, v.b) + h.fraction * at(h.b, v.b));
      if (r < cone.range_min_m) {
        r = -kInf;
      } else if (r > cone.range_max_m) {
        r = kInf;
      }
      // Half way between the rays around it (a single ray's own direction: yaw or pitch 0).
      const double yaw = 0.5 * (coneYaw(cone, h.a) + coneYaw(cone, h.b));
      const double pitch = 0.5 * (conePitch(cone, v.a) + conePitch(cone, v.b));
      Eigen::Vector3d p = r * coneDirection(yaw, pitch);
      if (std::fabs(cone.range_max_m - r) > 1e-6) {
        p += Eigen::Vector3d(noise(rng, spec.gaussian_noise), noise(rng, spec.gaussian_noise),
                             noise(rng, spec.gaussian_noise));
      }
      cloud.points.push_back(p.cast<float>());
      cloud.intensities.push_back(static_cast<float>(noise(rng, spec.gaussian_noise)));
    }
  }
  return cloud;
}

}  // namespace bullet_sim
