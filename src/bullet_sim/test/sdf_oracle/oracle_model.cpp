// Models, links and joints as libsdformat reads them.
#include "oracle_parts.h"

namespace bullet_sim_test {
namespace oracle {

namespace {

bullet_sim::SdfInertial inertialOf(const sdf::Link& link) {
  const ignition::math::Inertiald& inertial = link.Inertial();
  const ignition::math::MassMatrix3d& m = inertial.MassMatrix();
  bullet_sim::SdfInertial out;
  out.mass = m.Mass();
  out.ixx = m.Ixx();
  out.iyy = m.Iyy();
  out.izz = m.Izz();
  out.ixy = m.Ixy();
  out.ixz = m.Ixz();
  out.iyz = m.Iyz();
  out.T_link_inertial = toIsometry(inertial.Pose());
  return out;
}

/// libsdformat's enum as SDF names it; a type it does not know as the attribute says.
std::string jointTypeName(const sdf::Joint& joint) {
  switch (joint.Type()) {
    case sdf::JointType::BALL: return "ball";
    case sdf::JointType::CONTINUOUS: return "continuous";
    case sdf::JointType::FIXED: return "fixed";
    case sdf::JointType::GEARBOX: return "gearbox";
    case sdf::JointType::PRISMATIC: return "prismatic";
    case sdf::JointType::REVOLUTE: return "revolute";
    case sdf::JointType::REVOLUTE2: return "revolute2";
    case sdf::JointType::SCREW: return "screw";
    case sdf::JointType::UNIVERSAL: return "universal";
    default: return joint.Element() ? joint.Element()->Get<std::string>("type") : "";
  }
}

bullet_sim::SdfJointAxis axisOf(const sdf::JointAxis& axis, const std::string& what,
                                Problems* problems) {
  bullet_sim::SdfJointAxis out;
  ignition::math::Vector3d xyz;
  const sdf::Errors errors = axis.ResolveXyz(xyz, "__model__");
  if (errors.empty()) {
    out.xyz_in_model = toVector(xyz);
  } else {
    appendErrors(errors, what + " <axis> <xyz>", problems);
  }
  out.lower = axis.Lower();
  out.upper = axis.Upper();
  // JointAxis::Effort() and MaxVelocity() say +inf for a negative value (no limit); the
  // simulator's struct keeps the number, which libsdformat's tree holds (with the spec's
  // default -1 when absent).
  const sdf::ElementPtr limit = axis.Element() ? axis.Element()->GetElement("limit") : nullptr;
  out.effort = limit ? limit->Get<double>("effort") : -1;
  out.velocity = limit ? limit->Get<double>("velocity") : -1;
  out.damping = axis.Damping();
  out.friction = axis.Friction();
  out.spring_reference = axis.SpringReference();
  out.spring_stiffness = axis.SpringStiffness();
  return out;
}

}  // namespace

bullet_sim::SdfLink linkOf(const sdf::Link& link, Problems* problems) {
  bullet_sim::SdfLink out;
  out.name = link.Name();
  const sdf::ElementPtr element = link.Element();
  out.origin = originOf(element);
  out.T_model_link = resolvedPose(link.SemanticPose(), "", "link '" + out.name + "'", problems);
  out.inertial = inertialOf(link);
  // sdf::Link has no accessors for these three: its element tree does.
  out.gravity = element->Get<bool>("gravity");
  out.kinematic = element->Get<bool>("kinematic");
  out.self_collide = element->Get<bool>("self_collide");
  for (uint64_t i = 0; i < link.CollisionCount(); ++i) {
    out.collisions.push_back(collisionOf(*link.CollisionByIndex(i), problems));
  }
  for (uint64_t i = 0; i < link.VisualCount(); ++i) {
    out.visuals.push_back(visualOf(*link.VisualByIndex(i), problems));
  }
  for (uint64_t i = 0; i < link.SensorCount(); ++i) {
    out.sensors.push_back(sensorOf(*link.SensorByIndex(i), problems));
  }
  return out;
}

bullet_sim::SdfJoint jointOf(const sdf::Joint& joint, Problems* problems) {
  bullet_sim::SdfJoint out;
  // The name as written: for a file before 1.7 sdf::Model renames a joint that has a
  // link's name ("door" -> "door_joint", Model.cc); Gazebo classic and its plugins use
  // the written one.
  out.name = joint.Element() ? joint.Element()->Get<std::string>("name") : joint.Name();
  out.type = jointTypeName(joint);
  out.origin = originOf(joint.Element());
  out.parent = joint.ParentLinkName();
  out.child = joint.ChildLinkName();
  const std::string what = "joint '" + out.name + "'";
  out.T_model_joint = resolvedPose(joint.SemanticPose(), "__model__", what, problems);
  if (joint.Axis(0)) out.axis = axisOf(*joint.Axis(0), what, problems);
  return out;
}

namespace {

/// The canonical link of `model` and its pose in the model's frame: libsdformat names it,
/// and each nested model on the way to it gives its pose in its parent.
std::optional<OracleCanonicalLink> canonicalOf(const sdf::Model& model, Problems* problems) {
  const std::pair<const sdf::Link*, std::string> canonical =
      model.CanonicalLinkAndRelativeName();
  if (!canonical.first) return std::nullopt;
  OracleCanonicalLink out;
  out.scoped_name = canonical.second;
  const sdf::Model* scope = &model;
  std::string rest = canonical.second;
  for (size_t sep = rest.find("::"); sep != std::string::npos; sep = rest.find("::")) {
    scope = scope->ModelByName(rest.substr(0, sep));
    if (!scope) return std::nullopt;
    out.T_model_link = out.T_model_link *
        resolvedPose(scope->SemanticPose(), "", "model '" + scope->Name() + "'", problems);
    rest = rest.substr(sep + 2);
  }
  out.T_model_link = out.T_model_link *
      resolvedPose(canonical.first->SemanticPose(), "", "link '" + rest + "'", problems);
  return out;
}

}  // namespace

bullet_sim::SdfModel modelOf(const sdf::Model& model, const std::string& field_path,
                             OracleResult* result) {
  Problems* problems = &result->errors;
  bullet_sim::SdfModel out;
  out.name = model.Name();
  out.origin = originOf(model.Element());
  out.T_parent_model =
      resolvedPose(model.SemanticPose(), "", "model '" + out.name + "'", problems);
  out.is_static = model.Static();
  out.canonical_link = model.CanonicalLinkName();
  for (uint64_t i = 0; i < model.LinkCount(); ++i) {
    out.links.push_back(linkOf(*model.LinkByIndex(i), problems));
  }
  for (uint64_t i = 0; i < model.JointCount(); ++i) {
    out.joints.push_back(jointOf(*model.JointByIndex(i), problems));
  }
  for (uint64_t i = 0; i < model.ModelCount(); ++i) {
    const sdf::Model& nested = *model.ModelByIndex(i);
    out.models.push_back(modelOf(nested, modelFieldPath(field_path, nested.Name()), result));
  }
  out.plugins = pluginsOf(model.Element());
  if (const std::optional<OracleCanonicalLink> c = canonicalOf(model, problems)) {
    result->canonical_links[field_path] = *c;
  }
  return out;
}

}  // namespace oracle
}  // namespace bullet_sim_test
