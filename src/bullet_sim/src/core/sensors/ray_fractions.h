#ifndef BULLET_SIM_CORE_RAY_FRACTIONS_H
#define BULLET_SIM_CORE_RAY_FRACTIONS_H

#include <algorithm>
#include <cmath>
#include <utility>

#include <btBulletCollisionCommon.h>

namespace bullet_sim {

/// Fraction of the ray o + t d (t in [0, 1], box frame) where it enters the box of half
/// extents `half` centred on the origin: 0 if it starts inside, 1 if it misses.
inline double slabFraction(const btVector3& o, const btVector3& d, const btVector3& half) {
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
inline double boxFraction(const btTransform& T_world_box, const btMatrix3x3& R_box_world,
                          const btVector3& half, const btVector3& from, const btVector3& to) {
  return slabFraction(R_box_world * (from - T_world_box.getOrigin()), R_box_world * (to - from),
                      half);
}

/// Fraction of the ray from -> to where Bullet's narrowphase finds it hits `shape` of `obj`
/// posed at T_world_shape, if below `nearest`; else `nearest`.
double narrowphaseFraction(const btCollisionObject* obj, const btCollisionShape* shape,
                           const btTransform& T_world_shape, const btVector3& from,
                           const btVector3& to, double nearest);

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

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_RAY_FRACTIONS_H
