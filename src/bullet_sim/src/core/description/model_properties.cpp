#include "bullet_sim/description/model_properties.h"

#include <map>
#include <stdexcept>

namespace bullet_sim {
namespace {

const urdf::Link& findLink(const RobotSpec& spec, const std::string& link) {
  const urdf::LinkConstSharedPtr found = spec.urdf ? spec.urdf->getLink(link) : nullptr;
  if (!found) throw std::out_of_range("model '" + spec.name + "' has no link '" + link + "'");
  return *found;
}

}  // namespace

LinkInertia linkInertia(const RobotSpec& spec, const std::string& link) {
  const urdf::Link& l = findLink(spec, link);
  LinkInertia inertia;
  if (!l.inertial) return inertia;
  const urdf::Inertial& in = *l.inertial;
  inertia.mass_kg = in.mass;
  const urdf::Pose& o = in.origin;
  inertia.com_in_link.position = Eigen::Vector3d(o.position.x, o.position.y, o.position.z);
  inertia.com_in_link.orientation =
      Eigen::Quaterniond(o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z);
  inertia.ixx = in.ixx;
  inertia.ixy = in.ixy;
  inertia.ixz = in.ixz;
  inertia.iyy = in.iyy;
  inertia.iyz = in.iyz;
  inertia.izz = in.izz;
  return inertia;
}

std::vector<std::string> collisionNames(const RobotSpec& spec) {
  std::vector<std::string> names;
  if (!spec.urdf) return names;
  std::map<std::string, urdf::LinkSharedPtr> links(spec.urdf->links_.begin(),
                                                   spec.urdf->links_.end());
  for (const auto& entry : links) {
    int unnamed = 0;
    for (const urdf::CollisionSharedPtr& c : entry.second->collision_array) {
      if (!c) continue;
      if (!c->name.empty()) {
        names.push_back(c->name);
      } else {
        names.push_back(entry.first + "_collision" +
                        (unnamed > 0 ? "_" + std::to_string(unnamed) : ""));
        ++unnamed;
      }
    }
  }
  return names;
}

JointKind jointKind(const RobotSpec& spec, const std::string& joint) {
  const urdf::JointConstSharedPtr j = spec.urdf ? spec.urdf->getJoint(joint) : nullptr;
  if (!j) throw std::out_of_range("model '" + spec.name + "' has no joint '" + joint + "'");
  switch (j->type) {
    case urdf::Joint::REVOLUTE: return JointKind::Revolute;
    case urdf::Joint::CONTINUOUS: return JointKind::Continuous;
    case urdf::Joint::PRISMATIC: return JointKind::Prismatic;
    case urdf::Joint::FIXED: return JointKind::Fixed;
    default: return JointKind::Other;
  }
}

}  // namespace bullet_sim
