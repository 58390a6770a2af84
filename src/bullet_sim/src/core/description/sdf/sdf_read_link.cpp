#include "description/sdf/sdf_read_link.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// "__default__" is the value libsdformat gives a required string that is not written.
const char* const kDefault = "__default__";

const XMLElement* child(const XMLElement* e, const char* name) {
  return e ? e->FirstChildElement(name) : nullptr;
}

Geometry readShape(const XMLElement* shape, const std::string& type, const SdfValues& v) {
  if (type == "box") {
    const Eigen::Vector3d size = v.vector3(shape, "size", Eigen::Vector3d::Ones());
    return Geometry::box(size.x(), size.y(), size.z());
  }
  if (type == "cylinder") {
    return Geometry::cylinder(v.number(shape, "radius", 1), v.number(shape, "length", 1));
  }
  if (type == "sphere") return Geometry::sphere(v.number(shape, "radius", 1));
  if (type == "plane") {
    const Eigen::Vector2d size = v.vector2(shape, "size", Eigen::Vector2d::Ones());
    const Eigen::Vector3d normal = v.vector3(shape, "normal", Eigen::Vector3d::UnitZ());
    return Geometry::plane(size.x(), size.y(), normal.normalized());
  }
  return Geometry::mesh(v.text(shape, "uri", kDefault),
                        v.vector3(shape, "scale", Eigen::Vector3d::Ones()));
}

/// The <material> of a visual. The shorthand <script>NAME</script> (no <name> child) is
/// what sdformat 9 reads as a script of default name and uri, and Gazebo classic's
/// Visual::SetMaterial ignores the default name: the visual keeps its colours.
SdfMaterial readMaterial(const XMLElement* e, const SdfValues& v,
                         std::vector<std::string>* warnings) {
  SdfMaterial m;
  for (auto [name, colour] : {std::pair{"ambient", &m.ambient}, {"diffuse", &m.diffuse},
                              {"specular", &m.specular}, {"emissive", &m.emissive}}) {
    if (e->FirstChildElement(name)) *colour = v.color(e, name, Eigen::Vector4f::Zero());
  }
  m.lighting = v.boolean(e, "lighting", true);
  const XMLElement* script = e->FirstChildElement("script");
  if (!script) return m;
  for (const XMLElement* uri = script->FirstChildElement("uri"); uri;
       uri = uri->NextSiblingElement("uri")) {
    m.script_uris.push_back(SdfValues::text(uri));
  }
  const std::string name = v.text(script, "name", kDefault);
  m.script_name = name == kDefault ? "" : name;
  if (!script->FirstChildElement("name") && !SdfValues::text(script).empty()) {
    warnings->push_back(v.where(script) + ": '" + SdfValues::text(script) +
                        "' names no material: a <script> names it in <name> (and its files "
                        "in <uri>); Gazebo classic ignores this text and so does the simulator");
  }
  return m;
}

SdfVisual readVisual(const XMLElement* e, const SdfValues& v, const FrameScope& scope,
                     const std::string& link, const Eigen::Isometry3d& T_model_link,
                     std::vector<std::string>* warnings) {
  SdfVisual out;
  out.name = v.requiredAttribute(e, "name");
  out.origin = v.origin(e);
  out.T_link_visual = T_model_link.inverse() * scope.resolvePose(v.pose(e), link, e, v);
  out.geometry = readSdfGeometry(e, v);
  if (const XMLElement* m = e->FirstChildElement("material")) {
    out.material = readMaterial(m, v, warnings);
  }
  out.transparency = v.number(e, "transparency", 0);
  out.cast_shadows = v.boolean(e, "cast_shadows", true);
  return out;
}

SdfCollision readCollision(const XMLElement* e, const SdfValues& v, const FrameScope& scope,
                           const std::string& link, const Eigen::Isometry3d& T_model_link) {
  SdfCollision out;
  out.name = v.requiredAttribute(e, "name");
  out.origin = v.origin(e);
  out.T_link_collision = T_model_link.inverse() * scope.resolvePose(v.pose(e), link, e, v);
  out.geometry = readSdfGeometry(e, v);
  if (const XMLElement* ode = child(child(child(e, "surface"), "friction"), "ode")) {
    SdfFriction friction;
    if (ode->FirstChildElement("mu")) friction.mu = v.number(ode, "mu", 1);
    if (ode->FirstChildElement("mu2")) friction.mu2 = v.number(ode, "mu2", 1);
    out.ode_friction = friction;
  }
  return out;
}

SdfSensor readSensor(const XMLElement* e, const SdfValues& v, const FrameScope& scope,
                     const std::string& link, const Eigen::Isometry3d& T_model_link) {
  SdfSensor out;
  out.name = v.requiredAttribute(e, "name");
  out.type = v.requiredAttribute(e, "type");
  out.origin = v.origin(e);
  out.T_link_sensor = T_model_link.inverse() * scope.resolvePose(v.pose(e), link, e, v);
  out.update_rate_hz = v.number(e, "update_rate", 0);
  out.always_on = v.boolean(e, "always_on", false);
  out.visualize = v.boolean(e, "visualize", false);
  out.topic = v.text(e, "topic", "");
  out.plugins = readSdfPlugins(e, v);
  tinyxml2::XMLPrinter printer;
  e->Accept(&printer);
  out.xml = printer.CStr();
  return out;
}

SdfInertial readInertial(const XMLElement* e, const SdfValues& v) {
  SdfInertial out;
  if (!e) return out;
  out.mass = v.number(e, "mass", 1);
  out.T_link_inertial = v.pose(e).T;
  if (const XMLElement* i = e->FirstChildElement("inertia")) {
    out.ixx = v.number(i, "ixx", 1);
    out.iyy = v.number(i, "iyy", 1);
    out.izz = v.number(i, "izz", 1);
    out.ixy = v.number(i, "ixy", 0);
    out.ixz = v.number(i, "ixz", 0);
    out.iyz = v.number(i, "iyz", 0);
  }
  return out;
}

}  // namespace

SdfGeometry readSdfGeometry(const XMLElement* parent, const SdfValues& values) {
  SdfGeometry out;
  const XMLElement* g = parent->FirstChildElement("geometry");
  const XMLElement* shape = g ? g->FirstChildElement() : nullptr;
  if (!shape) return out;
  out.type = shape->Name();
  static const char* const kSimulated[] = {"box", "cylinder", "sphere", "plane", "mesh"};
  for (const char* kind : kSimulated) {
    if (out.type == kind) out.shape = readShape(shape, out.type, values);
  }
  if (out.type == "mesh") {
    if (const XMLElement* sub = shape->FirstChildElement("submesh")) {
      out.submesh = values.text(sub, "name", kDefault);
    }
  }
  return out;
}

SdfPlugin readSdfPlugin(const XMLElement* e, const SdfValues& values) {
  SdfPlugin out;
  out.name = SdfValues::attribute(e, "name");
  out.filename = values.requiredAttribute(e, "filename");
  tinyxml2::XMLPrinter printer;
  e->Accept(&printer);
  out.xml = printer.CStr();
  return out;
}

std::vector<SdfPlugin> readSdfPlugins(const XMLElement* parent, const SdfValues& values) {
  std::vector<SdfPlugin> out;
  for (const XMLElement* p = parent->FirstChildElement("plugin"); p;
       p = p->NextSiblingElement("plugin")) {
    out.push_back(readSdfPlugin(p, values));
  }
  return out;
}

SdfLink readSdfLink(const XMLElement* e, const SdfValues& values, const FrameScope& scope,
                    std::vector<std::string>* warnings) {
  SdfLink out;
  out.name = values.requiredAttribute(e, "name");
  out.origin = values.origin(e);
  out.T_model_link = scope.resolve(out.name, e, values);
  out.inertial = readInertial(e->FirstChildElement("inertial"), values);
  out.gravity = values.boolean(e, "gravity", true);
  out.kinematic = values.boolean(e, "kinematic", false);
  out.self_collide = values.boolean(e, "self_collide", false);
  for (const XMLElement* c = e->FirstChildElement("collision"); c;
       c = c->NextSiblingElement("collision")) {
    out.collisions.push_back(readCollision(c, values, scope, out.name, out.T_model_link));
  }
  for (const XMLElement* vis = e->FirstChildElement("visual"); vis;
       vis = vis->NextSiblingElement("visual")) {
    out.visuals.push_back(readVisual(vis, values, scope, out.name, out.T_model_link, warnings));
  }
  for (const XMLElement* s = e->FirstChildElement("sensor"); s;
       s = s->NextSiblingElement("sensor")) {
    out.sensors.push_back(readSensor(s, values, scope, out.name, out.T_model_link));
  }
  return out;
}

}  // namespace bullet_sim
