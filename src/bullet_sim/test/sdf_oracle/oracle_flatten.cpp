// Names with "::" in files before SDF 1.8, as Gazebo classic reads them: libsdformat 12's
// 1.7 -> 1.8 conversion turns a link "inner::link" of model m into a nested model "inner"
// holding "link" (Converter::Unflatten), where sdformat 9 and Gazebo classic keep the
// link "inner::link" of m. The models the conversion made have no line in the file.
#include <sstream>

#include "oracle_parts.h"

namespace bullet_sim_test {
namespace oracle {

namespace {

std::string scoped(const std::string& prefix, const std::string& name) {
  return name == "world" ? name : prefix + "::" + name;
}

/// The links, joints and models of `inner` moved into `outer`, named and posed there.
void moveInto(bullet_sim::SdfModel* outer, const bullet_sim::SdfModel& inner) {
  const Eigen::Isometry3d& T = inner.T_parent_model;
  for (bullet_sim::SdfLink link : inner.links) {
    link.name = scoped(inner.name, link.name);
    link.T_model_link = T * link.T_model_link;
    outer->links.push_back(link);
  }
  for (bullet_sim::SdfJoint joint : inner.joints) {
    joint.name = scoped(inner.name, joint.name);
    joint.parent = scoped(inner.name, joint.parent);
    joint.child = scoped(inner.name, joint.child);
    joint.T_model_joint = T * joint.T_model_joint;
    if (joint.axis) joint.axis->xyz_in_model = T.linear() * joint.axis->xyz_in_model;
    outer->joints.push_back(joint);
  }
  for (bullet_sim::SdfModel model : inner.models) {
    model.name = scoped(inner.name, model.name);
    model.T_parent_model = T * model.T_parent_model;
    outer->models.push_back(model);
  }
  outer->plugins.insert(outer->plugins.end(), inner.plugins.begin(), inner.plugins.end());
}

}  // namespace

bool unflattensNames(const std::string& version) {
  std::istringstream in(version);
  int major = 0, minor = 0;
  char dot = 0;
  return (in >> major >> dot >> minor) && (major < 1 || (major == 1 && minor < 8));
}

void flattenConverted(bullet_sim::SdfModel* model) {
  std::vector<bullet_sim::SdfModel> kept;
  for (bullet_sim::SdfModel& nested : model->models) {
    flattenConverted(&nested);
    if (nested.origin.line == 0) {
      moveInto(model, nested);
    } else {
      kept.push_back(nested);
    }
  }
  model->models = kept;
}

}  // namespace oracle
}  // namespace bullet_sim_test
