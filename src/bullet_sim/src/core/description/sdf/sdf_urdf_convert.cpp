#include "description/sdf/sdf_urdf_convert.h"

namespace bullet_sim {

urdf::Pose toUrdfPose(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  urdf::Pose p;
  p.position = urdf::Vector3(T.translation().x(), T.translation().y(), T.translation().z());
  p.rotation = urdf::Rotation(q.x(), q.y(), q.z(), q.w());
  return p;
}

}  // namespace bullet_sim
