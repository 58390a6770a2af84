#include "description/sdf/sdf_read_model.h"

#include <set>

#include "description/sdf/sdf_read_link.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// The joint types of SDF (libsdformat refuses any other).
const std::set<std::string> kJointTypes = {"revolute", "revolute2", "prismatic", "ball",
                                           "universal", "fixed",     "gearbox",   "screw",
                                           "continuous"};

class ModelReader {
 public:
  ModelReader(const XMLElement* e, const SdfValues& values, bool file_top,
              SdfReadContext* context)
      : e_(e), v_(values), file_top_(file_top), context_(context) {}

  ReadModel read(const IncludeOverrides& overrides) {
    ReadModel out;
    SdfModel& m = out.model;
    m.name = overrides.name ? *overrides.name : v_.requiredAttribute(e_, "name");
    m.origin = v_.origin(e_);
    m.is_static = overrides.is_static ? *overrides.is_static : v_.boolean(e_, "static", false);
    out.pose = overrides.pose ? *overrides.pose : v_.pose(e_);
    scope_ = std::make_unique<FrameScope>("__model__", "model '" + m.name + "'");
    registerFrames(&m);
    for (const XMLElement* l = e_->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
      m.links.push_back(readSdfLink(l, v_, *scope_, context_->warnings()));
    }
    for (const XMLElement* j = e_->FirstChildElement("joint"); j;
         j = j->NextSiblingElement("joint")) {
      m.joints.push_back(readJoint(j));
    }
    for (size_t i = 0; i < m.models.size(); ++i) {
      m.models[i].T_parent_model = scope_->resolve(m.models[i].name, nested_elements_[i], v_);
    }
    if (!v_.version().before(1, 7)) m.canonical_link = SdfValues::attribute(e_, "canonical_link");
    if (!m.canonical_link.empty() && !scope_->has(m.canonical_link)) {
      v_.fail(e_, "canonical_link '" + m.canonical_link + "' names no link of the model");
    }
    m.plugins = readSdfPlugins(e_, v_);
    m.plugins.insert(m.plugins.end(), overrides.plugins.begin(), overrides.plugins.end());
    out.frames = std::move(scope_);
    return out;
  }

 private:
  /// Links, <frame>s, nested and included models and joints, before any pose is resolved
  /// (a pose may be relative to a frame defined after it).
  void registerFrames(SdfModel* m) {
    for (const XMLElement* c = e_->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "link") {
        scope_->add(v_.requiredAttribute(c, "name"), v_.pose(c), "__model__", c, v_);
      } else if (tag == "frame") {
        const std::string attached = SdfValues::attribute(c, "attached_to");
        scope_->add(v_.requiredAttribute(c, "name"), v_.pose(c),
                    attached.empty() ? "__model__" : attached, c, v_);
      } else if (tag == "model") {
        addNested(readSdfModel(c, v_, false, {}, context_), c, m);
      } else if (tag == "include") {
        addIncluded(c, m);
      }
    }
    for (const XMLElement* j = e_->FirstChildElement("joint"); j;
         j = j->NextSiblingElement("joint")) {
      const std::string child = requiredText(j, "child");
      scope_->add(v_.requiredAttribute(j, "name"), v_.pose(j), child, j, v_);
    }
  }

  void addNested(ReadModel nested, const XMLElement* element, SdfModel* m) {
    scope_->add(nested.model.name, nested.pose, "__model__", element, v_);
    scope_->addNested(nested.model.name, std::move(nested.frames));
    m->models.push_back(std::move(nested.model));
    nested_elements_.push_back(element);
  }

  void addIncluded(const XMLElement* include, SdfModel* m) {
    const IncludeOverrides overrides = readIncludeOverrides(include, v_);
    const SdfReadContext::Included inc = context_->include(include, v_);
    if (std::string(inc.root->Name()) != "model") {
      context_->warnings()->push_back(v_.where(include) + ": includes a <" + inc.root->Name() +
                                      ">, which a model cannot hold: left out");
      context_->leave();
      return;
    }
    ReadModel nested = readSdfModel(inc.root, *inc.values, true, overrides, context_);
    context_->leave();
    // A pose written in the included file is relative to frames of that file only.
    if (!overrides.pose) nested.pose.relative_to.clear();
    addNested(std::move(nested), include, m);
  }

  std::string requiredText(const XMLElement* e, const char* name) const {
    const XMLElement* c = e->FirstChildElement(name);
    if (!c) v_.fail(e, std::string("the required element <") + name + "> is missing");
    return SdfValues::text(c);
  }

  SdfJoint readJoint(const XMLElement* j) {
    SdfJoint out;
    out.name = v_.requiredAttribute(j, "name");
    out.type = v_.requiredAttribute(j, "type");
    if (!kJointTypes.count(out.type)) {
      v_.fail(j, "type '" + out.type + "' is not a joint type of SDF (revolute, continuous, "
                 "prismatic, fixed, ball, universal, revolute2, screw, gearbox)");
    }
    out.origin = v_.origin(j);
    out.parent = requiredText(j, "parent");
    out.child = requiredText(j, "child");
    for (const std::string& link : {out.parent, out.child}) {
      if (link != "world" && !scope_->has(link)) {
        v_.fail(j, "'" + link + "' names no link of the model");
      }
    }
    out.T_model_joint = scope_->resolve(out.name, j, v_);
    out.axis = readAxis(j, out.T_model_joint);
    return out;
  }

  /// The first <axis>, its xyz in the model frame: SDF 1.4 writes the axes of a file's top
  /// model in the model frame, 1.5 and 1.6 in the joint frame unless
  /// <use_parent_model_frame>, 1.7 in the frame its expressed_in names (the joint's when
  /// none).
  std::optional<SdfJointAxis> readAxis(const XMLElement* j, const Eigen::Isometry3d& T_model_joint) {
    const XMLElement* a = j->FirstChildElement("axis");
    if (!a) return std::nullopt;
    SdfJointAxis axis;
    const Eigen::Vector3d xyz = v_.vector3(a, "xyz", Eigen::Vector3d::UnitZ());
    if (!(xyz.norm() > 0) || !xyz.allFinite()) {
      v_.fail(a->FirstChildElement("xyz"), "the axis must be a finite vector that is not zero");
    }
    Eigen::Matrix3d R = T_model_joint.linear();
    const SdfVersion version = v_.version();
    if (version.before(1, 5)) {
      if (file_top_) R.setIdentity();
    } else if (version.before(1, 7)) {
      if (v_.boolean(a, "use_parent_model_frame", false)) R.setIdentity();
    } else if (const XMLElement* x = a->FirstChildElement("xyz")) {
      const std::string frame = SdfValues::attribute(x, "expressed_in");
      if (frame == "__model__") R.setIdentity();
      else if (!frame.empty()) R = scope_->resolve(frame, x, v_).linear();
    }
    axis.xyz_in_model = R * xyz.normalized();
    if (const XMLElement* limit = a->FirstChildElement("limit")) {
      axis.lower = v_.number(limit, "lower", -1e16);
      axis.upper = v_.number(limit, "upper", 1e16);
      axis.effort = v_.number(limit, "effort", -1);
      axis.velocity = v_.number(limit, "velocity", -1);
    }
    if (const XMLElement* dynamics = a->FirstChildElement("dynamics")) {
      axis.damping = v_.number(dynamics, "damping", 0);
      axis.friction = v_.number(dynamics, "friction", 0);
      axis.spring_reference = v_.number(dynamics, "spring_reference", 0);
      axis.spring_stiffness = v_.number(dynamics, "spring_stiffness", 0);
    }
    return axis;
  }

  const XMLElement* e_;
  const SdfValues& v_;
  bool file_top_;
  SdfReadContext* context_;
  std::unique_ptr<FrameScope> scope_;
  std::vector<const XMLElement*> nested_elements_;  ///< of m.models, in order
};

}  // namespace

IncludeOverrides readIncludeOverrides(const XMLElement* include, const SdfValues& values) {
  IncludeOverrides o;
  if (const XMLElement* name = include->FirstChildElement("name")) o.name = SdfValues::text(name);
  if (include->FirstChildElement("pose")) o.pose = values.pose(include);
  if (include->FirstChildElement("static")) o.is_static = values.boolean(include, "static", false);
  o.plugins = readSdfPlugins(include, values);
  return o;
}

ReadModel readSdfModel(const XMLElement* e, const SdfValues& values, bool file_top,
                       const IncludeOverrides& overrides, SdfReadContext* context) {
  return ModelReader(e, values, file_top, context).read(overrides);
}

}  // namespace bullet_sim
