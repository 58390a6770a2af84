#include "description/sdf/sdf_util.h"

#include <cmath>
#include <sstream>

#include "bullet_sim/errors.h"
#include "description/material/gazebo_materials.h"

namespace bullet_sim {
namespace {

bool validSize(double v) { return v >= 0 && std::isfinite(v); }

}  // namespace

void checkGeometrySize(const SdfGeometry& geometry, const std::string& where) {
  if (!geometry.shape) return;
  const Eigen::Vector3d& size = geometry.shape->size;
  std::ostringstream value;
  std::string element;
  switch (geometry.shape->kind) {
    case Geometry::Box:
      if (validSize(size.x()) && validSize(size.y()) && validSize(size.z())) return;
      element = "<box> <size>";
      value << size.x() << " " << size.y() << " " << size.z();
      break;
    case Geometry::Cylinder: {
      const bool radius_ok = validSize(size.x());
      if (radius_ok && validSize(size.z())) return;
      element = radius_ok ? "<cylinder> <length>" : "<cylinder> <radius>";
      value << (radius_ok ? size.z() : size.x());
      break;
    }
    case Geometry::Sphere:
      if (validSize(size.x())) return;
      element = "<sphere> <radius>";
      value << size.x();
      break;
    default:
      return;
  }
  throw LoadError(where + ": " + element + ": '" + value.str() +
                  "' must be finite and not negative");
}

Eigen::Vector4f visualColour(const SdfVisual& visual, const std::string& where,
                             std::vector<std::string>* warnings) {
  const Eigen::Vector4f grey(0.7f, 0.7f, 0.7f, 1.0f);
  if (!visual.material) return grey;
  const SdfMaterial& material = *visual.material;
  if (material.diffuse) return *material.diffuse;
  if (material.script_name.empty()) return material.ambient ? *material.ambient : grey;
  if (const auto colour = gazeboMaterialColour(material.script_name)) return *colour;
  if (warnings) {
    warnings->push_back(where + ": material script '" + material.script_name +
                        "' is not one of Gazebo's stock materials: drawn grey");
  }
  return unknownMaterialColour();
}

}  // namespace bullet_sim
