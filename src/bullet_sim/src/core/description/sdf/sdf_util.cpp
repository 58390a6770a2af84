#include "description/sdf/sdf_util.h"

#include <cmath>
#include <sstream>

#include "bullet_sim/errors.h"
#include "description/material/gazebo_materials.h"

namespace bullet_sim {

Pose3 toPose(const ignition::math::Pose3d& p) {
  Pose3 out;
  out.position = Eigen::Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  out.orientation = Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z());
  return out;
}

ignition::math::Pose3d toSdfPose(const Pose3& p) {
  const Eigen::Quaterniond& q = p.orientation;
  return ignition::math::Pose3d(p.position.x(), p.position.y(), p.position.z(), q.w(), q.x(),
                                q.y(), q.z());
}

std::string geometryName(sdf::GeometryType type) {
  switch (type) {
    case sdf::GeometryType::EMPTY: return "empty";
    case sdf::GeometryType::BOX: return "box";
    case sdf::GeometryType::CYLINDER: return "cylinder";
    case sdf::GeometryType::PLANE: return "plane";
    case sdf::GeometryType::SPHERE: return "sphere";
    case sdf::GeometryType::MESH: return "mesh";
    case sdf::GeometryType::HEIGHTMAP: return "heightmap";
    case sdf::GeometryType::CAPSULE: return "capsule";
    case sdf::GeometryType::ELLIPSOID: return "ellipsoid";
    default: return "polyline";
  }
}

namespace {

bool validSize(double v) { return v >= 0 && std::isfinite(v); }

}  // namespace

void checkGeometrySize(const sdf::Geometry& geometry, const std::string& where) {
  std::ostringstream value;
  std::string element;
  if (const sdf::Box* box = geometry.BoxShape()) {
    const auto size = box->Size();
    if (validSize(size.X()) && validSize(size.Y()) && validSize(size.Z())) return;
    element = "<box> <size>";
    value << size.X() << " " << size.Y() << " " << size.Z();
  } else if (const sdf::Cylinder* cylinder = geometry.CylinderShape()) {
    const bool radius_ok = validSize(cylinder->Radius());
    if (radius_ok && validSize(cylinder->Length())) return;
    element = radius_ok ? "<cylinder> <length>" : "<cylinder> <radius>";
    value << (radius_ok ? cylinder->Length() : cylinder->Radius());
  } else if (const sdf::Sphere* sphere = geometry.SphereShape()) {
    if (validSize(sphere->Radius())) return;
    element = "<sphere> <radius>";
    value << sphere->Radius();
  } else {
    return;
  }
  throw LoadError(where + ": " + element + ": '" + value.str() +
                  "' must be finite and not negative");
}

Eigen::Vector4f visualColour(const sdf::Visual& visual, const std::string& where,
                             std::vector<std::string>* warnings) {
  const sdf::Material* material = visual.Material();
  if (!material) return Eigen::Vector4f(0.7f, 0.7f, 0.7f, 1.0f);
  // libsdformat reports absent colours as black: ask the element what was written.
  const sdf::ElementPtr element = material->Element();
  const auto rgba = [](const ignition::math::Color& c) {
    return Eigen::Vector4f(c.R(), c.G(), c.B(), c.A());
  };
  if (element && element->HasElement("diffuse")) return rgba(material->Diffuse());
  const std::string script = material->ScriptName();
  if (script.empty()) {
    if (element && element->HasElement("ambient")) return rgba(material->Ambient());
    return Eigen::Vector4f(0.7f, 0.7f, 0.7f, 1.0f);
  }
  if (const auto colour = gazeboMaterialColour(script)) return *colour;
  if (warnings) {
    warnings->push_back(where + ": material script '" + script +
                        "' is not one of Gazebo's stock materials: drawn grey");
  }
  return unknownMaterialColour();
}

std::string describe(const sdf::Errors& errors) {
  std::ostringstream out;
  for (size_t i = 0; i < errors.size(); ++i) out << (i ? "; " : "") << errors[i].Message();
  return out.str();
}

}  // namespace bullet_sim
