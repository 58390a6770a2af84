// Models, links, joints and inertials field by field.
#include "dom_compare.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

void compareInertials(DomComparer* cmp, const SdfInertial& ours, const SdfInertial& theirs) {
  cmp->number("mass", ours.mass, theirs.mass);
  cmp->number("ixx", ours.ixx, theirs.ixx);
  cmp->number("iyy", ours.iyy, theirs.iyy);
  cmp->number("izz", ours.izz, theirs.izz);
  cmp->number("ixy", ours.ixy, theirs.ixy);
  cmp->number("ixz", ours.ixz, theirs.ixz);
  cmp->number("iyz", ours.iyz, theirs.iyz);
  cmp->pose("T_link_inertial", ours.T_link_inertial, theirs.T_link_inertial);
}

void compareVisuals(DomComparer* cmp, const SdfVisual& ours, const SdfVisual& theirs) {
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->pose("T_link_visual", ours.T_link_visual, theirs.T_link_visual);
  {
    DomComparer::Scope scope(cmp, "geometry");
    compareGeometries(cmp, ours.geometry, theirs.geometry);
  }
  cmp->optional("material", ours.material, theirs.material,
                [cmp](const SdfMaterial& a, const SdfMaterial& b) {
                  compareMaterials(cmp, a, b);
                });
  cmp->number("transparency", ours.transparency, theirs.transparency, 1e-6);
  cmp->flag("cast_shadows", ours.cast_shadows, theirs.cast_shadows);
}

void compareCollisions(DomComparer* cmp, const SdfCollision& ours,
                       const SdfCollision& theirs) {
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->pose("T_link_collision", ours.T_link_collision, theirs.T_link_collision);
  {
    DomComparer::Scope scope(cmp, "geometry");
    compareGeometries(cmp, ours.geometry, theirs.geometry);
  }
  cmp->optional("ode_friction", ours.ode_friction, theirs.ode_friction,
                [cmp](const SdfFriction& a, const SdfFriction& b) {
                  const auto same = [cmp](const char* field, const std::optional<double>& x,
                                          const std::optional<double>& y) {
                    cmp->optional(field, x, y, [cmp](double p, double q) {
                      cmp->number("", p, q);
                    });
                  };
                  same("mu", a.mu, b.mu);
                  same("mu2", a.mu2, b.mu2);
                });
}

void compareSensors(DomComparer* cmp, const SdfSensor& ours, const SdfSensor& theirs) {
  cmp->text("type", ours.type, theirs.type);
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->pose("T_link_sensor", ours.T_link_sensor, theirs.T_link_sensor);
  cmp->number("update_rate_hz", ours.update_rate_hz, theirs.update_rate_hz);
  cmp->flag("always_on", ours.always_on, theirs.always_on);
  cmp->flag("visualize", ours.visualize, theirs.visualize);
  cmp->text("topic", ours.topic, theirs.topic);
  comparePlugins(cmp, "plugins", ours.plugins, theirs.plugins);
}

void compareLinks(DomComparer* cmp, const SdfLink& ours, const SdfLink& theirs) {
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->pose("T_model_link", ours.T_model_link, theirs.T_model_link);
  {
    DomComparer::Scope scope(cmp, "inertial");
    compareInertials(cmp, ours.inertial, theirs.inertial);
  }
  cmp->flag("gravity", ours.gravity, theirs.gravity);
  cmp->flag("kinematic", ours.kinematic, theirs.kinematic);
  cmp->flag("self_collide", ours.self_collide, theirs.self_collide);
  cmp->byName("collisions", ours.collisions, theirs.collisions,
              [cmp](const SdfCollision& a, const SdfCollision& b, const std::string&) {
                compareCollisions(cmp, a, b);
              });
  cmp->byName("visuals", ours.visuals, theirs.visuals,
              [cmp](const SdfVisual& a, const SdfVisual& b, const std::string&) {
                compareVisuals(cmp, a, b);
              });
  cmp->byName("sensors", ours.sensors, theirs.sensors,
              [cmp](const SdfSensor& a, const SdfSensor& b, const std::string&) {
                compareSensors(cmp, a, b);
              });
}

void compareAxes(DomComparer* cmp, const SdfJointAxis& ours, const SdfJointAxis& theirs) {
  cmp->vector("xyz_in_model", ours.xyz_in_model, theirs.xyz_in_model);
  cmp->number("lower", ours.lower, theirs.lower);
  cmp->number("upper", ours.upper, theirs.upper);
  cmp->number("effort", ours.effort, theirs.effort);
  cmp->number("velocity", ours.velocity, theirs.velocity);
  cmp->number("damping", ours.damping, theirs.damping);
  cmp->number("friction", ours.friction, theirs.friction);
  cmp->number("spring_reference", ours.spring_reference, theirs.spring_reference);
  cmp->number("spring_stiffness", ours.spring_stiffness, theirs.spring_stiffness);
}

void compareJoints(DomComparer* cmp, const SdfJoint& ours, const SdfJoint& theirs) {
  cmp->text("type", ours.type, theirs.type);
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->text("parent", ours.parent, theirs.parent);
  cmp->text("child", ours.child, theirs.child);
  cmp->pose("T_model_joint", ours.T_model_joint, theirs.T_model_joint);
  cmp->optional("axis", ours.axis, theirs.axis,
                [cmp](const SdfJointAxis& a, const SdfJointAxis& b) { compareAxes(cmp, a, b); });
}

void compareCanonical(DomComparer* cmp, const SdfModel& ours, const std::string& field_path,
                      const CanonicalLinks& canonical) {
  std::optional<std::pair<std::string, Eigen::Isometry3d>> theirs;
  const auto found = canonical.find(field_path);
  if (found != canonical.end()) {
    theirs = std::make_pair(found->second.scoped_name, found->second.T_model_link);
  }
  cmp->optional("canonicalLink()", ours.canonicalLink(), theirs,
                [cmp](const std::pair<std::string, Eigen::Isometry3d>& a,
                      const std::pair<std::string, Eigen::Isometry3d>& b) {
                  cmp->text("name", a.first, b.first);
                  cmp->pose("T_model_link", a.second, b.second);
                });
}

}  // namespace

void compareModels(DomComparer* cmp, const SdfModel& ours, const SdfModel& theirs,
                   const std::string& field_path, const CanonicalLinks& canonical) {
  cmp->text("name", ours.name, theirs.name);
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->pose("T_parent_model", ours.T_parent_model, theirs.T_parent_model);
  cmp->flag("is_static", ours.is_static, theirs.is_static);
  cmp->text("canonical_link", ours.canonical_link, theirs.canonical_link);
  compareCanonical(cmp, ours, field_path, canonical);
  cmp->byName("links", ours.links, theirs.links,
              [cmp](const SdfLink& a, const SdfLink& b, const std::string&) {
                compareLinks(cmp, a, b);
              });
  cmp->byName("joints", ours.joints, theirs.joints,
              [cmp](const SdfJoint& a, const SdfJoint& b, const std::string&) {
                compareJoints(cmp, a, b);
              });
  cmp->byName("models", ours.models, theirs.models,
              [&](const SdfModel& a, const SdfModel& b, const std::string& key) {
                compareModels(cmp, a, b, modelFieldPath(field_path, key), canonical);
              });
  comparePlugins(cmp, "plugins", ours.plugins, theirs.plugins);
}

}  // namespace bullet_sim_test
