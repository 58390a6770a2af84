#include "description/sdf/sdf_model.h"

#include <map>
#include <memory>

#include <urdf_model/model.h>

#include "bullet_sim/errors.h"
#include "description/robot_plan.h"
#include "description/gazebo/gazebo_extensions.h"
#include "description/sdf/sdf_model_entries.h"
#include "description/sdf/sdf_urdf_convert.h"
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
                    const UriResolver& resolver, bool is_static)
      : model_(model),
        source_(source),
        where_(source + ": model '" + model.name + "'"),
        resolver_(resolver),
        is_static_(is_static),
        links_(where_, resolver, &spec_, is_static) {}

  RobotSpec convert() {
    entries_ = ModelEntries::of(model_, where_, &spec_.warnings);
    const auto canonical = model_.canonicalLink();
    if (!canonical) throw LoadError(where_ + ": has no link");
    const std::string root = is_static_ ? canonical->first : entries_.treeRoot(canonical->first);
    urdf_ = std::make_shared<urdf::ModelInterface>();
    urdf_->name_ = model_.name;
    if (is_static_) {
      addStaticTree(root);
    } else {
      addSubtree(root);
      warnUnjoined(canonical->first);
    }
    initTree();
    spec_.name = model_.name;
    spec_.urdf = urdf_;
    spec_.root_link_in_model = toPose3(entries_.link(root, where_).T_model_link);
    addVisuals();
    // Mesh file names were resolved from the SDF file's folder above.
    loadRobotMeshes(resolver_, "", where_, &spec_);
    spec_.is_static = is_static_;
    std::vector<SdfPluginText> plugins;
    collectPlugins(model_, "model '" + model_.name + "'", &plugins);
    std::vector<SdfSensorText> sensors = links_.sensors();
    for (SdfSensorText& s : sensors) s.where = s.where.substr(source_.size() + 2);
    readSdfModelExtensions(sensors, plugins, source_, &spec_);
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

  /// A static model's links all stand still: each is fixed where the model puts it to the
  /// canonical link `root` (its joints do not move in Gazebo either).
  void addStaticTree(const std::string& root) {
    const LinkEntry& base = entries_.link(root, where_);
    urdf_->links_[root] = links_.convert(base);
    for (const LinkEntry& l : entries_.links) {
      if (l.name == root) continue;
      urdf_->links_[l.name] = links_.convert(l);
      auto joint = std::make_shared<urdf::Joint>();
      joint->name = root + "_to_" + l.name + "_static";
      joint->type = urdf::Joint::FIXED;
      joint->parent_link_name = root;
      joint->child_link_name = l.name;
      joint->parent_to_joint_origin_transform =
          toUrdfPose(base.T_model_link.inverse() * l.T_model_link);
      urdf_->joints_[joint->name] = joint;
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

  /// The <plugin>s of `m` and its nested models, each named by its model in `where`.
  static void collectPlugins(const SdfModel& m, const std::string& where,
                             std::vector<SdfPluginText>* out) {
    for (const SdfPlugin& p : m.plugins) out->push_back({p.xml, where + " "});
    for (const SdfModel& nested : m.models) {
      collectPlugins(nested, where + " model '" + nested.name + "'", out);
    }
  }

  const SdfModel& model_;
  std::string source_, where_;
  const UriResolver& resolver_;
  bool is_static_;
  RobotSpec spec_;
  SdfLinkConverter links_;
  ModelEntries entries_;
  urdf::ModelInterfaceSharedPtr urdf_;
};

}  // namespace

RobotSpec parseSdfModel(const SdfModel& model, const std::string& source,
                        const UriResolver& resolver) {
  return SdfModelConverter(model, source, resolver,
                           model.is_static || isAnchoredToWorld(model)).convert();
}

bool carriesSensorsOrPlugins(const SdfModel& model) {
  if (!model.plugins.empty()) return true;
  for (const SdfLink& l : model.links) {
    if (!l.sensors.empty()) return true;
  }
  for (const SdfModel& nested : model.models) {
    if (carriesSensorsOrPlugins(nested)) return true;
  }
  return false;
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
