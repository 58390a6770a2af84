#ifndef BULLET_SIM_CORE_SDF_MODEL_ENTRIES_H
#define BULLET_SIM_CORE_SDF_MODEL_ENTRIES_H

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// A link of the model or of one of its nested models, with its scoped name ("nested::link")
/// and pose in the top model's frame.
struct LinkEntry {
  const SdfLink* link;
  std::string name;
  Eigen::Isometry3d T_model_link;
};

/// A joint of the model or of one of its nested models, with scoped names, its pose and
/// axis in the top model's frame.
struct JointEntry {
  const SdfJoint* joint;
  std::string name, parent, child;
  Eigen::Isometry3d T_model_joint;
  Eigen::Vector3d axis_in_model{0, 0, 1};
};

/// The links and joints of a model and its nested models, as one list each.
struct ModelEntries {
  std::vector<LinkEntry> links;
  std::vector<JointEntry> joints;

  /// Every link and joint of `model`, posed in its frame. A joint to the world is left out,
  /// with a warning naming `where` and the joint.
  static ModelEntries of(const SdfModel& model, const std::string& where,
                         std::vector<std::string>* warnings);

  /// @throws LoadError naming `where` when there is no link `name`.
  const LinkEntry& link(const std::string& name, const std::string& where) const;

  /// The link above `canonical` that has no parent joint: URDF trees start there.
  std::string treeRoot(const std::string& canonical) const;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_MODEL_ENTRIES_H
