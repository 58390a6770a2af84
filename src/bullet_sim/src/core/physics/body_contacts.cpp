#include "physics/body_contacts.h"

#include <algorithm>

#include "physics/bullet_convert.h"

namespace bullet_sim {
namespace {

/// The compound child a manifold point's part index names, 0 for any other shape.
int partOf(const btCollisionObject* object, int index) {
  return object->getCollisionShape()->isCompound() && index >= 0 ? index : 0;
}

}  // namespace

std::vector<BodyContact> bodyContacts(btDispatcher& dispatcher, const btCollisionObject* body,
                                      double dt_s) {
  std::vector<BodyContact> contacts;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const bool is_a = manifold->getBody0() == body;
    if (!is_a && manifold->getBody1() != body) continue;
    const btCollisionObject* other = is_a ? manifold->getBody1() : manifold->getBody0();
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& pt = manifold->getContactPoint(p);
      if (pt.getDistance() > 0 && pt.getAppliedImpulse() <= 0) continue;
      // The solver pushes body A along the normal on B (and along the friction directions)
      // by the impulses it stores, body B the other way.
      const double sign = is_a ? 1.0 : -1.0;
      const btVector3 impulse = pt.m_normalWorldOnB * pt.m_appliedImpulse +
                                pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                                pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
      BodyContact c;
      c.part = partOf(body, is_a ? pt.m_index0 : pt.m_index1);
      c.other = other;
      c.other_part = partOf(other, is_a ? pt.m_index1 : pt.m_index0);
      c.position_m = toEigen(is_a ? pt.getPositionWorldOnA() : pt.getPositionWorldOnB());
      c.normal = sign * toEigen(pt.m_normalWorldOnB);
      c.force_n = sign * toEigen(impulse) / dt_s;
      c.torque_nm = (c.position_m - toEigen(body->getWorldTransform().getOrigin())).cross(c.force_n);
      c.depth_m = std::max(0.0, -static_cast<double>(pt.getDistance()));
      contacts.push_back(c);
    }
  }
  return contacts;
}

}  // namespace bullet_sim
