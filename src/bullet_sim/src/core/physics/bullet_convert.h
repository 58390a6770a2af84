#ifndef BULLET_SIM_CORE_BULLET_CONVERT_H
#define BULLET_SIM_CORE_BULLET_CONVERT_H

#include <btBulletDynamicsCommon.h>
#include <Eigen/Geometry>

namespace bullet_sim {

inline btVector3 toBt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

inline Eigen::Vector3d toEigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

inline btTransform toBt(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), toBt(T.translation()));
}

inline Eigen::Isometry3d toEigen(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(toEigen(t.getOrigin()));
  T.rotate(Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()));
  return T;
}

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_BULLET_CONVERT_H
