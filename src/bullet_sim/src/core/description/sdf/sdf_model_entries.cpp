#include "description/sdf/sdf_model_entries.h"

#include <set>

#include "bullet_sim/errors.h"
#include "description/sdf/sdf_urdf_convert.h"
#include "description/sdf/sdf_util.h"

namespace bullet_sim {
namespace {

using Eigen::Isometry3d;

std::string scoped(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "::" + name;
}

/// Joint `j` of a model whose links are named under `prefix` and posed at T_top_m.
JointEntry jointEntry(const sdf::Joint& j, const std::string& prefix, const Isometry3d& T_top_m) {
  JointEntry e{&j, scoped(prefix, j.Name()), "", "", T_top_m, {0, 0, 1}};
  std::string parent = j.ParentLinkName(), child = j.ChildLinkName();
  j.ResolveParentLink(parent);
  j.ResolveChildLink(child);
  e.parent = parent == "world" ? parent : scoped(prefix, parent);
  e.child = scoped(prefix, child);
  ignition::math::Pose3d pose;
  if (j.SemanticPose().Resolve(pose, "__model__").empty()) {
    e.T_model_joint = T_top_m * sdfToIsometry(pose);
  }
  ignition::math::Vector3d xyz(0, 0, 1);
  if (j.Axis(0) && j.Axis(0)->ResolveXyz(xyz, "__model__").empty()) {
    e.axis_in_model = T_top_m.linear() * Eigen::Vector3d(xyz.X(), xyz.Y(), xyz.Z());
  }
  return e;
}

void collect(const sdf::Model& m, const std::string& prefix, const Isometry3d& T_top_m,
             const std::string& where, ModelEntries* entries, std::vector<std::string>* warnings) {
  for (uint64_t i = 0; i < m.LinkCount(); ++i) {
    const sdf::Link& l = *m.LinkByIndex(i);
    entries->links.push_back(
        {&l, scoped(prefix, l.Name()), T_top_m * sdfToIsometry(poseInParent(l))});
  }
  for (uint64_t i = 0; i < m.JointCount(); ++i) {
    const JointEntry e = jointEntry(*m.JointByIndex(i), prefix, T_top_m);
    if (e.parent == "world") {
      warnings->push_back(where + ": joint '" + e.name + "' to the world is left out: " +
                          "the model moves freely");
      continue;
    }
    entries->joints.push_back(e);
  }
  for (uint64_t i = 0; i < m.ModelCount(); ++i) {
    const sdf::Model& nested = *m.ModelByIndex(i);
    collect(nested, scoped(prefix, nested.Name()),
            T_top_m * sdfToIsometry(poseInParent(nested)), where, entries, warnings);
  }
}

}  // namespace

ModelEntries ModelEntries::of(const sdf::Model& model, const std::string& where,
                              std::vector<std::string>* warnings) {
  ModelEntries entries;
  collect(model, "", Isometry3d::Identity(), where, &entries, warnings);
  return entries;
}

const LinkEntry& ModelEntries::link(const std::string& name, const std::string& where) const {
  for (const LinkEntry& l : links) {
    if (l.name == name) return l;
  }
  throw LoadError(where + ": no link named '" + name + "'");
}

std::string ModelEntries::treeRoot(const std::string& canonical) const {
  std::string root = canonical;
  std::set<std::string> seen{root};
  for (bool moved = true; moved;) {
    moved = false;
    for (const JointEntry& j : joints) {
      if (j.child == root && !seen.count(j.parent)) {
        root = j.parent;
        seen.insert(root);
        moved = true;
        break;
      }
    }
  }
  return root;
}

}  // namespace bullet_sim
