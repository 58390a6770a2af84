#include "description/sdf/sdf_model_entries.h"

#include <set>

#include "bullet_sim/errors.h"

namespace bullet_sim {
namespace {

using Eigen::Isometry3d;

std::string scoped(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "::" + name;
}

/// Joint `j` of a model whose links are named under `prefix` and posed at T_top_m.
JointEntry jointEntry(const SdfJoint& j, const std::string& prefix, const Isometry3d& T_top_m) {
  JointEntry e{&j, scoped(prefix, j.name), "", "", T_top_m * j.T_model_joint, {0, 0, 1}};
  e.parent = j.parent == "world" ? j.parent : scoped(prefix, j.parent);
  e.child = scoped(prefix, j.child);
  if (j.axis) e.axis_in_model = T_top_m.linear() * j.axis->xyz_in_model;
  return e;
}

void collect(const SdfModel& m, const std::string& prefix, const Isometry3d& T_top_m,
             const std::string& where, ModelEntries* entries, std::vector<std::string>* warnings) {
  for (const SdfLink& l : m.links) {
    entries->links.push_back({&l, scoped(prefix, l.name), T_top_m * l.T_model_link});
  }
  for (const SdfJoint& j : m.joints) {
    const JointEntry e = jointEntry(j, prefix, T_top_m);
    if (e.parent == "world") {
      warnings->push_back(where + ": joint '" + e.name + "' to the world is left out: " +
                          "the model moves freely");
      continue;
    }
    entries->joints.push_back(e);
  }
  for (const SdfModel& nested : m.models) {
    collect(nested, scoped(prefix, nested.name), T_top_m * nested.T_parent_model, where,
            entries, warnings);
  }
}

}  // namespace

ModelEntries ModelEntries::of(const SdfModel& model, const std::string& where,
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
