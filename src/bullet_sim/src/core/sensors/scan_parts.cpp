#include "sensors/scan_parts.h"

#include <algorithm>
#include <cmath>

#include "sensors/ray_fractions.h"

namespace bullet_sim {

bool ScanParts::gather(btCollisionWorld& world, double range, size_t max_parts) {
  if (!poseIsFinite() || !std::isfinite(range)) return false;
  const btVector3 reach(range, range, range);
  const btVector3& origin = T_world_sensor_.getOrigin();
  reach_min_ = origin - reach;
  reach_max_ = origin + reach;
  world.getBroadphase()->aabbTest(reach_min_, reach_max_, *this);
  if (!listParts(max_parts)) return false;
  indexRays();
  return true;
}

bool ScanParts::poseIsFinite() const {
  const btMatrix3x3& R = T_world_sensor_.getBasis();
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(R[i][0]) || !std::isfinite(R[i][1]) || !std::isfinite(R[i][2]) ||
        !std::isfinite(T_world_sensor_.getOrigin()[i])) {
      return false;
    }
  }
  return true;
}

bool ScanParts::listParts(size_t max_parts) {
  for (const btCollisionObject* obj : objects_) {
    forEachLeaf(obj->getCollisionShape(), obj->getWorldTransform(),
                [this, obj](const btCollisionShape* shape, const btTransform& T_world_shape) {
                  addShape(obj, shape, T_world_shape);
                });
    if (parts_.size() > max_parts) return false;
  }
  return true;
}

void ScanParts::indexRays() {
  // Each part's runs of rays, then the parts of each ray in one array.
  std::vector<Run> runs;
  for (size_t p = 0; p < parts_.size(); ++p) addRuns(static_cast<int>(p), &runs);
  for (const Run& run : runs) {
    for (int k = run[1]; k <= run[2]; ++k) ++first_[k + 1];
  }
  for (int k = 0; k < samples_; ++k) first_[k + 1] += first_[k];
  ray_parts_.resize(first_[samples_]);
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (const Run& run : runs) {
    for (int k = run[1]; k <= run[2]; ++k) ray_parts_[next[k]++] = run[0];
  }
}

double ScanParts::nearestHit(int k, const btVector3& from, const btVector3& to) const {
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

bool ScanParts::process(const btBroadphaseProxy* proxy) {
  // The filter of a ray callback with Bullet's default group and mask.
  if ((proxy->m_collisionFilterGroup & btBroadphaseProxy::AllFilter) != 0 &&
      (btBroadphaseProxy::DefaultFilter & proxy->m_collisionFilterMask) != 0) {
    objects_.push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject));
  }
  return true;
}

void ScanParts::addShape(const btCollisionObject* obj, const btCollisionShape* shape,
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

void ScanParts::addRuns(int p, std::vector<Run>* runs) const {
  btVector3 corners[8];
  sensorCorners(parts_[p], corners);
  if (!nearScanPlane(corners)) return;
  const Arc arc = azimuthArc(corners);
  if (surroundsAxis(corners) || arc.gap <= M_PI || !(increment_ > 0)) {
    if (samples_ > 0) runs->push_back({p, 0, samples_ - 1});
    return;
  }
  addArcRuns(p, arc.start - kPad, arc.start + (2 * M_PI - arc.gap) + kPad, runs);
}

void ScanParts::sensorCorners(const Part& part, btVector3 corners[8]) const {
  for (int c = 0; c < 8; ++c) {
    const btVector3 sign(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
    corners[c] = part.box ? part.T_world_shape(part.half * sign)
                          : btVector3(part.aabb[c & 1 ? 1 : 0].x(), part.aabb[c & 2 ? 1 : 0].y(),
                                      part.aabb[c & 4 ? 1 : 0].z());
    corners[c] = T_world_sensor_.invXform(corners[c]);
  }
}

bool ScanParts::nearScanPlane(const btVector3 corners[8]) {
  double z_min = corners[0].z(), z_max = z_min;
  for (int c = 0; c < 8; ++c) {
    z_min = std::min(z_min, corners[c].z());
    z_max = std::max(z_max, corners[c].z());
  }
  return !(z_min > kPad || z_max < -kPad);
}

bool ScanParts::surroundsAxis(const btVector3 corners[8]) {
  for (int c = 0; c < 8; ++c) {
    if (std::hypot(corners[c].x(), corners[c].y()) < 1e-9) return true;
  }
  return false;
}

ScanParts::Arc ScanParts::azimuthArc(const btVector3 corners[8]) {
  // The directions to a convex body that does not surround the axis form an arc of less
  // than half a turn: the largest gap between its corners' azimuths is then the rest.
  double azimuth[8];
  for (int c = 0; c < 8; ++c) azimuth[c] = std::atan2(corners[c].y(), corners[c].x());
  std::sort(azimuth, azimuth + 8);
  Arc arc{azimuth[0], azimuth[0] + 2 * M_PI - azimuth[7]};
  for (int c = 1; c < 8; ++c) {
    if (azimuth[c] - azimuth[c - 1] > arc.gap) {
      arc.gap = azimuth[c] - azimuth[c - 1];
      arc.start = azimuth[c];
    }
  }
  return arc;
}

void ScanParts::addArcRuns(int p, double lo, double hi, std::vector<Run>* runs) const {
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

}  // namespace bullet_sim
