#include "ray_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bullet_convert.h"

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

  bool needsCollision(btBroadphaseProxy* proxy) const override {
    if (!ClosestRayResultCallback::needsCollision(proxy)) return false;
    const auto* obj = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    const int type = obj->getCollisionShape()->getShapeType();
    if (type != BOX_SHAPE_PROXYTYPE && type != COMPOUND_SHAPE_PROXYTYPE) return true;
    const_cast<BoxAwareRayCallback*>(this)->testShape(obj, obj->getCollisionShape(),
                                                      obj->getWorldTransform());
    return false;
  }

 private:
  void testShape(const btCollisionObject* obj, const btCollisionShape* shape,
                 const btTransform& T_world_shape) {
    if (shape->getShapeType() == BOX_SHAPE_PROXYTYPE) {
      const auto* box = static_cast<const btBoxShape*>(shape);
      const double t = slabFraction(T_world_shape, box->getHalfExtentsWithMargin());
      if (t < m_closestHitFraction) {
        m_closestHitFraction = t;
        m_collisionObject = obj;
      }
    } else if (shape->getShapeType() == COMPOUND_SHAPE_PROXYTYPE) {
      const auto* compound = static_cast<const btCompoundShape*>(shape);
      for (int i = 0; i < compound->getNumChildShapes(); ++i) {
        testShape(obj, compound->getChildShape(i), T_world_shape * compound->getChildTransform(i));
      }
    } else {
      btVector3 aabb_min, aabb_max;
      shape->getAabb(T_world_shape, aabb_min, aabb_max);
      btScalar t = m_closestHitFraction;
      btVector3 unused_normal;
      if (!btRayAabb(m_rayFromWorld, m_rayToWorld, aabb_min, aabb_max, t, unused_normal)) return;
      btTransform from = btTransform::getIdentity(), to = btTransform::getIdentity();
      from.setOrigin(m_rayFromWorld);
      to.setOrigin(m_rayToWorld);
      btCollisionWorld::rayTestSingle(from, to, const_cast<btCollisionObject*>(obj), shape,
                                      T_world_shape, *this);
    }
  }

 private:
  /// Fraction of the ray where it enters the box, or 1 if it misses.
  double slabFraction(const btTransform& box_in_world, const btVector3& half) const {
    const btVector3 o = box_in_world.invXform(m_rayFromWorld);
    const btVector3 d = box_in_world.getBasis().transpose() * (m_rayToWorld - m_rayFromWorld);
    double t_near = 0.0, t_far = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      if (std::fabs(d[axis]) < 1e-15) {
        if (std::fabs(o[axis]) > half[axis]) return 1.0;
        continue;
      }
      double t0 = (-half[axis] - o[axis]) / d[axis];
      double t1 = (half[axis] - o[axis]) / d[axis];
      if (t0 > t1) std::swap(t0, t1);
      t_near = std::max(t_near, t0);
      t_far = std::min(t_far, t1);
      if (t_near > t_far) return 1.0;
    }
    return t_near;
  }
};

}  // namespace

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
    BoxAwareRayCallback hit(from, to);
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
