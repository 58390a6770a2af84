#include "sensors/ray_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/bullet_convert.h"
#include "sensors/ray_fractions.h"
#include "sensors/scan_parts.h"

namespace bullet_sim {
namespace {

/// Bullet's broadphase and filtering, with boxes intersected exactly by slabs:
/// Bullet's general convex ray cast iterates (about 13k instructions per
/// box a ray's bounding box touches), and walls and most robot parts are
/// boxes. Compounds are opened here so that their boxes take the same path;
/// every other shape (cylinders, spheres, the triangle meshes of static world
/// meshes, the convex hulls of robot meshes) goes to Bullet's own narrowphase.
class BoxAwareRayCallback : public btCollisionWorld::ClosestRayResultCallback {
 public:
  using ClosestRayResultCallback::ClosestRayResultCallback;
  /// Objects of this user index are not hit.
  int ignored_index = kNoIgnoredIndex;

  bool needsCollision(btBroadphaseProxy* proxy) const override {
    if (!ClosestRayResultCallback::needsCollision(proxy)) return false;
    const auto* obj = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    if (obj->getUserIndex() == ignored_index) return false;
    const int type = obj->getCollisionShape()->getShapeType();
    if (type != BOX_SHAPE_PROXYTYPE && type != COMPOUND_SHAPE_PROXYTYPE) return true;
    auto* self = const_cast<BoxAwareRayCallback*>(this);
    forEachLeaf(obj->getCollisionShape(), obj->getWorldTransform(),
                [self, obj](const btCollisionShape* shape, const btTransform& T_world_shape) {
                  self->testShape(obj, shape, T_world_shape);
                });
    return false;
  }

 private:
  /// `shape` is not a compound.
  void testShape(const btCollisionObject* obj, const btCollisionShape* shape,
                 const btTransform& T_world_shape) {
    double t = m_closestHitFraction;
    if (shape->getShapeType() == BOX_SHAPE_PROXYTYPE) {
      t = boxFraction(T_world_shape, T_world_shape.getBasis().transpose(),
                      static_cast<const btBoxShape*>(shape)->getHalfExtentsWithMargin(),
                      m_rayFromWorld, m_rayToWorld);
    } else {
      btVector3 aabb_min, aabb_max;
      shape->getAabb(T_world_shape, aabb_min, aabb_max);
      btScalar entry = m_closestHitFraction;
      btVector3 unused_normal;
      if (!btRayAabb(m_rayFromWorld, m_rayToWorld, aabb_min, aabb_max, entry, unused_normal)) {
        return;
      }
      t = narrowphaseFraction(obj, shape, T_world_shape, m_rayFromWorld, m_rayToWorld,
                              m_closestHitFraction);
    }
    if (t < m_closestHitFraction) {
      m_closestHitFraction = t;
      m_collisionObject = obj;
    }
  }
};

}  // namespace

double firstHitFraction(btCollisionWorld& world, const btVector3& from, const btVector3& to,
                        int ignored_index) {
  BoxAwareRayCallback hit(from, to);
  hit.ignored_index = ignored_index;
  world.rayTest(from, to, hit);
  return hit.hasHit() ? hit.m_closestHitFraction : 1.0;
}

bool castScan(btCollisionWorld& world, const Eigen::Isometry3d& T_world_sensor,
              const RaySpec& spec, std::mt19937_64* rng, LaserScanData* scan,
              size_t max_listed_parts, bool may_walk) {
  const double increment =
      spec.samples > 1 ? (spec.max_angle_rad - spec.min_angle_rad) / (spec.samples - 1) : 0.0;
  ScanParts parts(toBt(T_world_sensor), spec.min_angle_rad, increment,
                  std::max(spec.samples, 0));
  const bool by_direction = parts.gather(world, spec.range_max_m, max_listed_parts);
  if (!by_direction && !may_walk) return false;
  scan->frame_id = spec.frame_id;
  scan->angle_min = spec.min_angle_rad;
  scan->angle_max = spec.max_angle_rad;
  scan->angle_increment = increment;
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
    double fraction = 1.0;
    if (by_direction) {
      fraction = parts.nearestHit(i, from, to);
    } else {
      BoxAwareRayCallback hit(from, to);
      world.rayTest(from, to, hit);
      if (hit.hasHit()) fraction = hit.m_closestHitFraction;
    }
    if (fraction >= 1.0) continue;
    double range = spec.range_min_m + fraction * span;
    if (noisy) range += noise(*rng);
    if (spec.range_resolution_m > 0) {
      range = std::round(range / spec.range_resolution_m) * spec.range_resolution_m;
    }
    scan->ranges[i] = static_cast<float>(std::clamp(range, spec.range_min_m, spec.range_max_m));
  }
  return true;
}

}  // namespace bullet_sim
