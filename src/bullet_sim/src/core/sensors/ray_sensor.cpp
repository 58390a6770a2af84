#include "sensors/ray_sensor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "physics/bullet_convert.h"

namespace bullet_sim {
namespace {

/// Fraction of the ray o + t d (t in [0, 1], box frame) where it enters the box of half
/// extents `half` centred on the origin: 0 if it starts inside, 1 if it misses.
double slabFraction(const btVector3& o, const btVector3& d, const btVector3& half) {
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

/// Fraction of the ray from -> to where it enters the box of half extents `half` posed at
/// T_world_box, whose rotation transposed is R_box_world: 0 if it starts inside, 1 if it
/// misses.
double boxFraction(const btTransform& T_world_box, const btMatrix3x3& R_box_world,
                   const btVector3& half, const btVector3& from, const btVector3& to) {
  return slabFraction(R_box_world * (from - T_world_box.getOrigin()), R_box_world * (to - from),
                      half);
}

/// Fraction of the ray from -> to where Bullet's narrowphase finds it hits `shape` of `obj`
/// posed at T_world_shape, if below `nearest`; else `nearest`.
double narrowphaseFraction(const btCollisionObject* obj, const btCollisionShape* shape,
                           const btTransform& T_world_shape, const btVector3& from,
                           const btVector3& to, double nearest) {
  btCollisionWorld::ClosestRayResultCallback hit(from, to);
  hit.m_closestHitFraction = nearest;
  btTransform T_from = btTransform::getIdentity(), T_to = btTransform::getIdentity();
  T_from.setOrigin(from);
  T_to.setOrigin(to);
  btCollisionWorld::rayTestSingle(T_from, T_to, const_cast<btCollisionObject*>(obj), shape,
                                  T_world_shape, hit);
  return hit.hasHit() ? hit.m_closestHitFraction : nearest;
}

/// Calls visit(leaf, T_world_leaf) for `shape` posed at T_world_shape, or for every shape in
/// it when it is a compound (nested compounds opened too).
template <class Visit>
void forEachLeaf(const btCollisionShape* shape, const btTransform& T_world_shape, Visit&& visit) {
  if (shape->getShapeType() != COMPOUND_SHAPE_PROXYTYPE) {
    visit(shape, T_world_shape);
    return;
  }
  const auto* compound = static_cast<const btCompoundShape*>(shape);
  for (int i = 0; i < compound->getNumChildShapes(); ++i) {
    forEachLeaf(compound->getChildShape(i), T_world_shape * compound->getChildTransform(i), visit);
  }
}

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

/// The parts a planar scan can hit, gathered once per scan from Bullet's broadphase (the
/// objects whose bounding boxes lie within range), compounds opened, and each listed for
/// the rays of the directions it covers as seen from the sensor: a ray then tests the few
/// parts in its direction (on the round track 1.5 boxes a ray on average) instead of a
/// walk of the broadphase tree and a slab test of every box whose bounding box it crosses.
/// Boxes are intersected by slabs, as above; every other shape goes to Bullet's narrowphase.
class ScanParts : public btBroadphaseAabbCallback {
 public:
  /// Sample k of the scan looks along azimuth angle_min + k * increment in the sensor frame.
  ScanParts(const btTransform& T_world_sensor, double angle_min, double increment, int samples)
      : T_world_sensor_(T_world_sensor),
        angle_min_(angle_min),
        increment_(increment),
        samples_(samples),
        first_(samples + 1, 0) {}

  /// Lists the objects within `range` of the sensor; false if they make more than
  /// `max_parts` parts, or if the sensor's pose or the range is not finite.
  bool gather(btCollisionWorld& world, double range, size_t max_parts) {
    const btMatrix3x3& R = T_world_sensor_.getBasis();
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(R[i][0]) || !std::isfinite(R[i][1]) || !std::isfinite(R[i][2]) ||
          !std::isfinite(T_world_sensor_.getOrigin()[i])) {
        return false;
      }
    }
    if (!std::isfinite(range)) return false;
    const btVector3 reach(range, range, range);
    const btVector3& origin = T_world_sensor_.getOrigin();
    reach_min_ = origin - reach;
    reach_max_ = origin + reach;
    world.getBroadphase()->aabbTest(reach_min_, reach_max_, *this);
    for (const btCollisionObject* obj : objects_) {
      forEachLeaf(obj->getCollisionShape(), obj->getWorldTransform(),
                  [this, obj](const btCollisionShape* shape, const btTransform& T_world_shape) {
                    addShape(obj, shape, T_world_shape);
                  });
      if (parts_.size() > max_parts) return false;
    }
    // Each part's runs of rays, then the parts of each ray in one array.
    std::vector<std::array<int, 3>> runs;  // part, first ray, last ray
    for (size_t p = 0; p < parts_.size(); ++p) addRuns(static_cast<int>(p), &runs);
    for (const auto& run : runs) {
      for (int k = run[1]; k <= run[2]; ++k) ++first_[k + 1];
    }
    for (int k = 0; k < samples_; ++k) first_[k + 1] += first_[k];
    ray_parts_.resize(first_[samples_]);
    std::vector<int> next(first_.begin(), first_.end() - 1);
    for (const auto& run : runs) {
      for (int k = run[1]; k <= run[2]; ++k) ray_parts_[next[k]++] = run[0];
    }
    return true;
  }

  /// Fraction along from -> to (sample `k`) of the nearest hit, or 1 for none.
  double nearestHit(int k, const btVector3& from, const btVector3& to) const {
    double nearest = 1.0;
    const btVector3 delta = to - from;  // btRayAabb2's ray: from + t delta
    btVector3 inverse;
    unsigned int negative[3];
    for (int axis = 0; axis < 3; ++axis) {
      inverse[axis] = delta[axis] == 0 ? BT_LARGE_FLOAT : 1 / delta[axis];
      negative[axis] = inverse[axis] < 0;
    }
    for (int j = first_[k]; j < first_[k + 1]; ++j) {
      const Part& part = parts_[ray_parts_[j]];
      if (part.box) {
        nearest = std::min(
            nearest, boxFraction(part.T_world_shape, part.R_shape_world, part.half, from, to));
        continue;
      }
      btScalar t_enter;
      if (!btRayAabb2(from, inverse, negative, part.aabb, t_enter, 0, nearest)) continue;
      nearest = narrowphaseFraction(part.obj, part.shape, part.T_world_shape, from, to, nearest);
    }
    return nearest;
  }

  bool process(const btBroadphaseProxy* proxy) override {
    // The filter of a ray callback with Bullet's default group and mask.
    if ((proxy->m_collisionFilterGroup & btBroadphaseProxy::AllFilter) != 0 &&
        (btBroadphaseProxy::DefaultFilter & proxy->m_collisionFilterMask) != 0) {
      objects_.push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject));
    }
    return true;
  }

 private:
  struct Part {
    const btCollisionObject* obj;
    const btCollisionShape* shape;
    btTransform T_world_shape;
    bool box;
    btMatrix3x3 R_shape_world;
    btVector3 half;  ///< a box's half extents, margin included
    btVector3 aabb[2];  ///< its bounding box within the scan's reach: minimum, maximum
  };

  /// `shape` is not a compound.
  void addShape(const btCollisionObject* obj, const btCollisionShape* shape,
                const btTransform& T_world_shape) {
    Part part{obj, shape, T_world_shape, shape->getShapeType() == BOX_SHAPE_PROXYTYPE,
              T_world_shape.getBasis().transpose(), {}, {}};
    if (part.box) part.half = static_cast<const btBoxShape*>(shape)->getHalfExtentsWithMargin();
    shape->getAabb(T_world_shape, part.aabb[0], part.aabb[1]);
    // Rays stay within the reach: what lies beyond it is never hit, and a plane's endless
    // box becomes one whose corners can be turned into the sensor's frame.
    part.aabb[0].setMax(reach_min_);
    part.aabb[1].setMin(reach_max_);
    for (int axis = 0; axis < 3; ++axis) {
      if (part.aabb[0][axis] > part.aabb[1][axis]) return;
    }
    parts_.push_back(part);
  }

  /// The runs of rays whose azimuths part `p`'s corners span (a box's own corners, any
  /// other shape's bounding box corners): all rays if it surrounds the sensor's axis, none if
  /// it lies wholly above or below the scan plane.
  void addRuns(int p, std::vector<std::array<int, 3>>* runs) const {
    const Part& part = parts_[p];
    btVector3 corners[8];
    for (int c = 0; c < 8; ++c) {
      const btVector3 sign(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
      corners[c] = part.box ? part.T_world_shape(part.half * sign)
                            : btVector3(part.aabb[c & 1 ? 1 : 0].x(), part.aabb[c & 2 ? 1 : 0].y(),
                                        part.aabb[c & 4 ? 1 : 0].z());
      corners[c] = T_world_sensor_.invXform(corners[c]);
    }
    double z_min = corners[0].z(), z_max = z_min;
    double azimuth[8];
    bool around_axis = false;
    for (int c = 0; c < 8; ++c) {
      z_min = std::min(z_min, corners[c].z());
      z_max = std::max(z_max, corners[c].z());
      if (std::hypot(corners[c].x(), corners[c].y()) < 1e-9) around_axis = true;
      azimuth[c] = std::atan2(corners[c].y(), corners[c].x());
    }
    if (z_min > kPad || z_max < -kPad) return;
    // The directions to a convex body that does not surround the axis form an arc of less
    // than half a turn: the largest gap between its corners' azimuths is then the rest.
    std::sort(azimuth, azimuth + 8);
    double gap = azimuth[0] + 2 * M_PI - azimuth[7];
    double arc_start = azimuth[0];
    for (int c = 1; c < 8; ++c) {
      if (azimuth[c] - azimuth[c - 1] > gap) {
        gap = azimuth[c] - azimuth[c - 1];
        arc_start = azimuth[c];
      }
    }
    if (around_axis || gap <= M_PI || !(increment_ > 0)) {
      if (samples_ > 0) runs->push_back({p, 0, samples_ - 1});
      return;
    }
    const double lo = arc_start - kPad, hi = arc_start + (2 * M_PI - gap) + kPad;
    // Every turn of the arc that meets [angle_min, angle_max].
    const double angle_max = angle_min_ + (samples_ - 1) * increment_;
    for (double shift = std::floor((angle_min_ - hi) / (2 * M_PI)) * 2 * M_PI;
         lo + shift <= angle_max; shift += 2 * M_PI) {
      const double first = std::ceil((lo + shift - angle_min_) / increment_);
      const double last = std::floor((hi + shift - angle_min_) / increment_);
      const int k0 = static_cast<int>(std::clamp(first, 0.0, static_cast<double>(samples_)));
      const int k1 = static_cast<int>(std::clamp(last, -1.0, samples_ - 1.0));
      if (k0 <= k1) runs->push_back({p, k0, k1});
    }
  }

  static constexpr double kPad = 1e-6;  ///< radians and metres kept around each part

  btTransform T_world_sensor_;
  btVector3 reach_min_, reach_max_;  ///< the box around the sensor that every ray stays in
  double angle_min_, increment_;
  int samples_;
  std::vector<const btCollisionObject*> objects_;
  std::vector<Part> parts_;
  std::vector<int> first_;      ///< ray k's parts are ray_parts_[first_[k] .. first_[k + 1])
  std::vector<int> ray_parts_;
};

}  // namespace

void castScan(btCollisionWorld& world, const Eigen::Isometry3d& T_world_sensor,
              const RaySpec& spec, std::mt19937_64* rng, LaserScanData* scan,
              size_t max_listed_parts) {
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
  ScanParts parts(toBt(T_world_sensor), spec.min_angle_rad, scan->angle_increment,
                  std::max(spec.samples, 0));
  const bool by_direction = parts.gather(world, spec.range_max_m, max_listed_parts);
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
}

}  // namespace bullet_sim
