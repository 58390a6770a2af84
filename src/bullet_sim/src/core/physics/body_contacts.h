#ifndef BULLET_SIM_CORE_BODY_CONTACTS_H
#define BULLET_SIM_CORE_BODY_CONTACTS_H

#include <vector>

#include <btBulletCollisionCommon.h>
#include <Eigen/Core>

namespace bullet_sim {

/// One point where something touches a body, from the contact manifolds of the last step,
/// in world axes, as Gazebo's contact sensor reports it for the body's collision.
struct BodyContact {
  int part = 0;  ///< the child of the body's compound shape touched (0 for a single shape)
  const btCollisionObject* other = nullptr;
  int other_part = 0;  ///< the same for the other object, when it is a compound
  Eigen::Vector3d position_m{0, 0, 0};  ///< the point on the body's surface
  Eigen::Vector3d normal{0, 0, 1};      ///< unit, pointing into the body (it pushes it out)
  /// Force on the body (N): the solver's normal and friction impulses of the last step / dt.
  Eigen::Vector3d force_n{0, 0, 0};
  Eigen::Vector3d torque_nm{0, 0, 0};  ///< of that force about the body's centre of mass
  double depth_m = 0;  ///< how far the two overlap, >= 0
};

/// The contact points of `body` in `dispatcher`'s manifolds (points that overlap or that
/// the solver pushed on), after a step of dt_s.
std::vector<BodyContact> bodyContacts(btDispatcher& dispatcher, const btCollisionObject* body,
                                      double dt_s);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_BODY_CONTACTS_H
