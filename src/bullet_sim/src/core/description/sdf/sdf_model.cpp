#include "description/sdf/sdf_model.h"

#include <map>
#include <memory>

#include <urdf_model/model.h>

#include "bullet_sim/errors.h"
#include "description/robot_plan.h"
#include "description/sdf/sdf_model_entries.h"
#include "description/sdf/sdf_urdf_joint.h"
#include "description/sdf/sdf_urdf_link.h"
#include "description/urdf/robot_parser.h"

namespace bullet_sim {
namespace {

/// Turns an SDF model into a URDF tree from the link above its canonical link, then into
/// a RobotSpec: links, joints and their visuals' textures and meshes, plugins warned about.
class SdfModelConverter {
 public:
  SdfModelConverter(const SdfModel& model, const std::string& source,
                    const UriResolver& resolver)
      : model_(model),
        where_(source + ": model '" + model.name + "'"),
        resolver_(resolver),
        links_(where_, resolver, &spec_) {}

  RobotSpec convert() {
    entries_ = ModelEntries::of(model_, where_, &spec_.warnings);
    const auto canonical = model_.canonicalLink();
    if (!canonical) throw LoadError(where_ + ": has no link");
    const std::string root = entries_.treeRoot(canonical->first);
    urdf_ = std::make_shared<urdf::ModelInterface>();
    urdf_->name_ = model_.name;
    addSubtree(root);
    warnUnjoined(canonical->first);
    initTree();
    spec_.name = model_.name;
    spec_.urdf = urdf_;
    spec_.root_link_in_model = toPose3(entries_.link(root, where_).T_model_link);
    addVisuals();
    // Mesh file names were resolved from the SDF file's folder above.
    loadRobotMeshes(resolver_, "", where_, &spec_);
    warnAboutPlugins(model_);
    return std::move(spec_);
  }

 private:
  void addSubtree(const std::string& name) {
    const LinkEntry& entry = entries_.link(name, where_);
    urdf_->links_[name] = links_.convert(entry);
    for (const JointEntry& j : entries_.joints) {
      if (j.parent != name) continue;
      if (urdf_->links_.count(j.child)) {
        spec_.warnings.push_back(where_ + ": joint '" + j.name + "' closes a loop: left out");
        continue;
      }
      addUrdfJoint(j, entry, entries_.link(j.child, where_), where_, urdf_.get(),
                   &spec_.warnings);
      addSubtree(j.child);
    }
  }

  void warnUnjoined(const std::string& canonical) {
    for (const LinkEntry& l : entries_.links) {
      if (!urdf_->links_.count(l.name)) {
        spec_.warnings.push_back(where_ + ": link '" + l.name + "' is not joined to the " +
                                 "canonical link '" + canonical + "': not simulated");
      }
    }
  }

  void initTree() {
    std::map<std::string, std::string> parent_of;
    try {
      urdf_->initTree(parent_of);
      urdf_->initRoot(parent_of);
    } catch (const std::exception& e) {
      throw LoadError(where_ + ": its links do not form a tree: " + e.what());
    }
  }

  /// The visual specs of every link, with the textures of their material scripts.
  void addVisuals() {
    std::vector<urdf::LinkSharedPtr> links;
    urdf_->getLinks(links);
    const std::map<const urdf::Visual*, TextureRef>& textures = links_.textures();
    for (const urdf::LinkSharedPtr& l : links) {
      size_t next = spec_.visuals.size();
      addLinkVisuals(*l, &spec_);
      for (const urdf::VisualSharedPtr& v : l->visual_array) {  // as addLinkVisuals walks them
        if (!v || !v->geometry) continue;
        const auto texture = textures.find(v.get());
        if (texture != textures.end()) spec_.visuals[next].texture = texture->second;
        ++next;
      }
    }
  }

  void warnAboutPlugins(const SdfModel& m) {
    for (const SdfPlugin& p : m.plugins) {
      spec_.warnings.push_back(where_ + ": plugin '" + p.filename + "' is not supported: ignored");
    }
    for (const SdfModel& nested : m.models) warnAboutPlugins(nested);
  }

  const SdfModel& model_;
  std::string where_;
  const UriResolver& resolver_;
  RobotSpec spec_;
  SdfLinkConverter links_;
  ModelEntries entries_;
  urdf::ModelInterfaceSharedPtr urdf_;
};

}  // namespace

RobotSpec parseSdfModel(const SdfModel& model, const std::string& source,
                        const UriResolver& resolver) {
  RobotSpec spec = SdfModelConverter(model, source, resolver).convert();
  // Only spawned models come here static (a world file's static models are static shapes).
  spec.is_static = model.is_static;
  return spec;
}

bool isAnchoredToWorld(const SdfModel& model, std::string* joint_name, bool* fixed) {
  for (const SdfJoint& j : model.joints) {
    if (j.parent != "world") continue;
    if (joint_name) *joint_name = j.name;
    if (fixed) *fixed = j.type == "fixed";
    return true;
  }
  for (const SdfModel& nested : model.models) {
    if (isAnchoredToWorld(nested, joint_name, fixed)) return true;
  }
  return false;
}

}  // namespace bullet_sim
