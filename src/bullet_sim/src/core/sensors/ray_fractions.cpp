#include "sensors/ray_fractions.h"

namespace bullet_sim {

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

}  // namespace bullet_sim
