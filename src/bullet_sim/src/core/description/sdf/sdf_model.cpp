#include "description/sdf/sdf_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include <urdf_model/model.h>

#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/material/visual_appearance.h"
#include "description/robot_plan.h"
#include "description/sdf/sdf_surface.h"
#include "description/sdf/sdf_util.h"
#include "description/urdf/robot_parser.h"
#include "description/urdf/urdf_checks.h"

namespace bullet_sim {
namespace {

using Eigen::Isometry3d;

/// SDF writes an unlimited revolute joint as limits beyond +-1e16.
constexpr double kUnlimited = 1e15;

Isometry3d toIso(const ignition::math::Pose3d& p) { return toIsometry(toPose(p)); }

urdf::Pose toUrdf(const Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  urdf::Pose p;
  p.position = urdf::Vector3(T.translation().x(), T.translation().y(), T.translation().z());
  p.rotation = urdf::Rotation(q.x(), q.y(), q.z(), q.w());
  return p;
}

std::string scoped(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "::" + name;
}

/// A link or joint of the model or of one of its nested models, with its scoped name
/// and pose in the top model's frame.
struct LinkEntry {
  const sdf::Link* link;
  std::string name;
  Isometry3d T_model_link;
};
struct JointEntry {
  const sdf::Joint* joint;
  std::string name, parent, child;
  Isometry3d T_model_joint;
  Eigen::Vector3d axis_in_model{0, 0, 1};
};

class SdfModelConverter {
 public:
  SdfModelConverter(const sdf::Model& model, const std::string& source,
                    const UriResolver& resolver)
      : model_(model),
        source_(source),
        where_(source + ": model '" + model.Name() + "'"),
        resolver_(resolver) {}

  RobotSpec convert() {
    collect(model_, "", Isometry3d::Identity());
    const auto canonical = model_.CanonicalLinkAndRelativeName();
    if (!canonical.first) throw LoadError(where_ + ": has no link");
    const std::string root = treeRoot(canonical.second);
    urdf_ = std::make_shared<urdf::ModelInterface>();
    urdf_->name_ = model_.Name();
    addSubtree(root);
    for (const LinkEntry& l : links_) {
      if (!urdf_->links_.count(l.name)) {
        spec_.warnings.push_back(where_ + ": link '" + l.name + "' is not joined to the " +
                                 "canonical link '" + canonical.second + "': not simulated");
      }
    }
    std::map<std::string, std::string> parent_of;
    try {
      urdf_->initTree(parent_of);
      urdf_->initRoot(parent_of);
    } catch (const std::exception& e) {
      throw LoadError(where_ + ": its links do not form a tree: " + e.what());
    }
    spec_.name = model_.Name();
    spec_.urdf = urdf_;
    spec_.root_link_in_model = toPose3(link(root).T_model_link);
    std::vector<urdf::LinkSharedPtr> links;
    urdf_->getLinks(links);
    for (const urdf::LinkSharedPtr& l : links) {
      size_t next = spec_.visuals.size();
      addLinkVisuals(*l, &spec_);
      for (const urdf::VisualSharedPtr& v : l->visual_array) {  // as addLinkVisuals walks them
        if (!v || !v->geometry) continue;
        const auto texture = textures_.find(v.get());
        if (texture != textures_.end()) spec_.visuals[next].texture = texture->second;
        ++next;
      }
    }
    // Mesh file names were resolved from the SDF file's folder above.
    loadRobotMeshes(resolver_, "", where_, &spec_);
    warnAboutPlugins(model_);
    return std::move(spec_);
  }

 private:
  void collect(const sdf::Model& m, const std::string& prefix, const Isometry3d& T_top_m) {
    for (uint64_t i = 0; i < m.LinkCount(); ++i) {
      const sdf::Link& l = *m.LinkByIndex(i);
      links_.push_back({&l, scoped(prefix, l.Name()), T_top_m * toIso(poseInParent(l))});
    }
    for (uint64_t i = 0; i < m.JointCount(); ++i) {
      const sdf::Joint& j = *m.JointByIndex(i);
      JointEntry e{&j, scoped(prefix, j.Name()), "", "", T_top_m, {0, 0, 1}};
      std::string parent = j.ParentLinkName(), child = j.ChildLinkName();
      j.ResolveParentLink(parent);
      j.ResolveChildLink(child);
      e.parent = parent == "world" ? parent : scoped(prefix, parent);
      e.child = scoped(prefix, child);
      ignition::math::Pose3d pose;
      if (j.SemanticPose().Resolve(pose, "__model__").empty()) e.T_model_joint = T_top_m * toIso(pose);
      ignition::math::Vector3d xyz(0, 0, 1);
      if (j.Axis(0) && j.Axis(0)->ResolveXyz(xyz, "__model__").empty()) {
        e.axis_in_model = T_top_m.linear() * Eigen::Vector3d(xyz.X(), xyz.Y(), xyz.Z());
      }
      if (e.parent == "world") {
        spec_.warnings.push_back(where_ + ": joint '" + e.name + "' to the world is left out: " +
                                 "the model moves freely");
        continue;
      }
      joints_.push_back(e);
    }
    for (uint64_t i = 0; i < m.ModelCount(); ++i) {
      const sdf::Model& nested = *m.ModelByIndex(i);
      collect(nested, scoped(prefix, nested.Name()), T_top_m * toIso(poseInParent(nested)));
    }
  }

  const LinkEntry& link(const std::string& name) const {
    for (const LinkEntry& l : links_) {
      if (l.name == name) return l;
    }
    throw LoadError(where_ + ": no link named '" + name + "'");
  }

  /// The link above `canonical` that has no parent joint: URDF trees start there.
  std::string treeRoot(const std::string& canonical) const {
    std::string root = canonical;
    std::set<std::string> seen{root};
    for (bool moved = true; moved;) {
      moved = false;
      for (const JointEntry& j : joints_) {
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

  void addSubtree(const std::string& name) {
    const LinkEntry& entry = link(name);
    urdf_->links_[name] = makeLink(entry);
    for (const JointEntry& j : joints_) {
      if (j.parent != name) continue;
      if (urdf_->links_.count(j.child)) {
        spec_.warnings.push_back(where_ + ": joint '" + j.name + "' closes a loop: left out");
        continue;
      }
      addJoint(j, entry);
      addSubtree(j.child);
    }
  }

  /// URDF puts a joint at its child link's origin. A joint elsewhere in its child gets an
  /// intermediate massless link at the joint, fixed to the child (Bullet merges the two).
  void addJoint(const JointEntry& j, const LinkEntry& parent) {
    const LinkEntry& child = link(j.child);
    const Isometry3d T_joint_child = j.T_model_joint.inverse() * child.T_model_link;
    auto joint = makeJoint(j);
    joint->parent_link_name = parent.name;
    joint->parent_to_joint_origin_transform = toUrdf(parent.T_model_link.inverse() * j.T_model_joint);
    const Eigen::Vector3d axis = j.T_model_joint.linear().transpose() * j.axis_in_model;
    joint->axis = urdf::Vector3(axis.x(), axis.y(), axis.z());
    if (T_joint_child.isApprox(Isometry3d::Identity(), 1e-9)) {
      joint->child_link_name = child.name;
    } else {
      const std::string frame = j.name + "_frame";
      auto frame_link = std::make_shared<urdf::Link>();
      frame_link->name = frame;
      urdf_->links_[frame] = frame_link;
      joint->child_link_name = frame;
      auto fixed = std::make_shared<urdf::Joint>();
      fixed->name = j.name + "_frame_to_child";
      fixed->type = urdf::Joint::FIXED;
      fixed->parent_link_name = frame;
      fixed->child_link_name = child.name;
      fixed->parent_to_joint_origin_transform = toUrdf(T_joint_child);
      urdf_->joints_[fixed->name] = fixed;
    }
    urdf_->joints_[joint->name] = joint;
  }

  urdf::JointSharedPtr makeJoint(const JointEntry& j) {
    auto joint = std::make_shared<urdf::Joint>();
    joint->name = j.name;
    const sdf::JointAxis* axis = j.joint->Axis(0);
    const auto limits = [&] {
      auto l = std::make_shared<urdf::JointLimits>();
      l->lower = axis->Lower();
      l->upper = axis->Upper();
      l->effort = axis->Effort();
      l->velocity = axis->MaxVelocity();
      return l;
    };
    switch (j.joint->Type()) {
      case sdf::JointType::FIXED:
        joint->type = urdf::Joint::FIXED;
        break;
      case sdf::JointType::CONTINUOUS:
        joint->type = urdf::Joint::CONTINUOUS;
        break;
      case sdf::JointType::REVOLUTE:
        joint->type = axis && (axis->Lower() > -kUnlimited || axis->Upper() < kUnlimited)
                          ? urdf::Joint::REVOLUTE
                          : urdf::Joint::CONTINUOUS;
        if (joint->type == urdf::Joint::REVOLUTE) joint->limits = limits();
        break;
      case sdf::JointType::PRISMATIC:
        joint->type = urdf::Joint::PRISMATIC;
        if (axis) joint->limits = limits();
        break;
      default:
        spec_.warnings.push_back(where_ + ": joint '" + j.name + "': type not supported " +
                                 "(revolute, continuous, prismatic, fixed are): held fixed");
        joint->type = urdf::Joint::FIXED;
    }
    if (axis && joint->type != urdf::Joint::FIXED) {
      joint->dynamics = std::make_shared<urdf::JointDynamics>();
      joint->dynamics->damping = axis->Damping();
      joint->dynamics->friction = axis->Friction();
    }
    return joint;
  }

  urdf::LinkSharedPtr makeLink(const LinkEntry& entry) {
    const sdf::Link& l = *entry.link;
    auto out = std::make_shared<urdf::Link>();
    out->name = entry.name;
    const ignition::math::Inertiald& in = l.Inertial();
    out->inertial = std::make_shared<urdf::Inertial>();
    out->inertial->origin = toUrdf(toIso(in.Pose()));
    out->inertial->mass = in.MassMatrix().Mass();
    out->inertial->ixx = in.MassMatrix().Ixx();
    out->inertial->iyy = in.MassMatrix().Iyy();
    out->inertial->izz = in.MassMatrix().Izz();
    out->inertial->ixy = in.MassMatrix().Ixy();
    out->inertial->ixz = in.MassMatrix().Ixz();
    out->inertial->iyz = in.MassMatrix().Iyz();
    const std::string where = where_ + " link '" + entry.name + "'";
    // libsdformat only warns about a bad inertia (static links may have one); a moving
    // link cannot be simulated with it.
    checkInertial(*out->inertial, where);
    for (uint64_t i = 0; i < l.CollisionCount(); ++i) {
      const sdf::Collision& c = *l.CollisionByIndex(i);
      auto col = std::make_shared<urdf::Collision>();
      col->name = c.Name();
      col->origin = toUrdf(toIso(poseInParent(c)));
      const std::string cwhere = where + " collision '" + c.Name() + "'";
      col->geometry = geometry(*c.Geom(), cwhere);
      out->collision_array.push_back(col);
      readFriction(c, entry.name, cwhere);
    }
    for (uint64_t i = 0; i < l.VisualCount(); ++i) {
      const sdf::Visual& v = *l.VisualByIndex(i);
      const std::string vwhere = where + " visual '" + v.Name() + "'";
      auto vis = std::make_shared<urdf::Visual>();
      vis->name = v.Name();
      vis->origin = toUrdf(toIso(poseInParent(v)));
      vis->geometry = geometry(*v.Geom(), vwhere);
      const Appearance look = visualAppearance(v, vwhere, source_, resolver_, &spec_.warnings);
      const Eigen::Vector4f& rgba = look.rgba;
      if (!look.texture.path.empty()) textures_[vis.get()] = look.texture;
      vis->material = std::make_shared<urdf::Material>();
      vis->material->color.r = rgba[0];
      vis->material->color.g = rgba[1];
      vis->material->color.b = rgba[2];
      vis->material->color.a = rgba[3];
      out->visual_array.push_back(vis);
    }
    if (!out->collision_array.empty()) out->collision = out->collision_array.front();
    if (!out->visual_array.empty()) out->visual = out->visual_array.front();
    for (uint64_t i = 0; i < l.SensorCount(); ++i) {
      spec_.warnings.push_back(where + ": sensor '" + l.SensorByIndex(i)->Name() +
                               "' is not simulated (sensors of SDF models are not)");
    }
    return out;
  }

  /// A mesh's file is resolved here, from the folder of the SDF file that names it: the
  /// URDF model carries the path.
  urdf::GeometrySharedPtr geometry(const sdf::Geometry& g, const std::string& where) const {
    checkGeometrySize(g, where);
    std::optional<Geometry> geometry = geometryOf(g);
    if (!geometry || geometry->kind == Geometry::Plane) {
      throw LoadError(where + ": geometry type '" + geometryName(g.Type()) +
                      "' is not supported for a movable model (box, cylinder, sphere, " +
                      "mesh are)");
    }
    if (geometry->kind == Geometry::Mesh) {
      const std::string base =
          std::filesystem::path(g.MeshShape()->FilePath()).parent_path().string();
      const std::string path = resolver_.resolve(geometry->mesh_uri, base);
      if (!path.empty()) geometry->mesh_uri = path;
    }
    return urdfGeometry(*geometry);
  }

  /// <surface><friction><ode><mu>/<mu2> of a collision, as the URDF <gazebo> tags give them.
  void readFriction(const sdf::Collision& c, const std::string& link, const std::string& where) {
    const auto known = spec_.surfaces.find(link);
    SurfaceParams s = known == spec_.surfaces.end() ? SurfaceParams() : known->second;
    if (readOdeFriction(c, where, &s)) spec_.surfaces[link] = s;
  }

  void warnAboutPlugins(const sdf::Model& m) {
    const sdf::ElementPtr e = m.Element();
    for (sdf::ElementPtr p = e ? e->FindElement("plugin") : nullptr; p;
         p = p->GetNextElement("plugin")) {
      spec_.warnings.push_back(where_ + ": plugin '" + p->Get<std::string>("filename") +
                               "' is not supported: ignored");
    }
    for (uint64_t i = 0; i < m.ModelCount(); ++i) warnAboutPlugins(*m.ModelByIndex(i));
  }

  const sdf::Model& model_;
  std::string source_;
  std::string where_;
  const UriResolver& resolver_;
  /// Material script textures of the visuals, until the specs of the visuals exist.
  std::map<const urdf::Visual*, TextureRef> textures_;
  std::vector<LinkEntry> links_;
  std::vector<JointEntry> joints_;
  urdf::ModelInterfaceSharedPtr urdf_;
  RobotSpec spec_;
};

}  // namespace

RobotSpec parseSdfModel(const sdf::Model& model, const std::string& source,
                        const UriResolver& resolver) {
  return SdfModelConverter(model, source, resolver).convert();
}

bool isAnchoredToWorld(const sdf::Model& model, std::string* joint_name, bool* fixed) {
  for (uint64_t i = 0; i < model.JointCount(); ++i) {
    const sdf::Joint& j = *model.JointByIndex(i);
    if (j.ParentLinkName() != "world") continue;
    if (joint_name) *joint_name = j.Name();
    if (fixed) *fixed = j.Type() == sdf::JointType::FIXED;
    return true;
  }
  for (uint64_t i = 0; i < model.ModelCount(); ++i) {
    if (isAnchoredToWorld(*model.ModelByIndex(i), joint_name, fixed)) return true;
  }
  return false;
}

}  // namespace bullet_sim
