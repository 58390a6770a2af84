#include "description/description_geometry.h"

namespace bullet_sim {

Geometry geometryOf(const urdf::Geometry& geometry) {
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(geometry);
      return Geometry::box(b.dim.x, b.dim.y, b.dim.z);
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(geometry);
      return Geometry::cylinder(c.radius, c.length);
    }
    case urdf::Geometry::SPHERE:
      return Geometry::sphere(static_cast<const urdf::Sphere&>(geometry).radius);
    case urdf::Geometry::MESH:
      break;
  }
  const auto& m = static_cast<const urdf::Mesh&>(geometry);
  return Geometry::mesh(m.filename, Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z));
}

urdf::GeometrySharedPtr urdfGeometry(const Geometry& geometry) {
  const Eigen::Vector3d& s = geometry.size;
  switch (geometry.kind) {
    case Geometry::Box: {
      auto box = std::make_shared<urdf::Box>();
      box->dim = urdf::Vector3(s.x(), s.y(), s.z());
      return box;
    }
    case Geometry::Cylinder: {
      auto cylinder = std::make_shared<urdf::Cylinder>();
      cylinder->radius = s.x();
      cylinder->length = s.z();
      return cylinder;
    }
    case Geometry::Sphere: {
      auto sphere = std::make_shared<urdf::Sphere>();
      sphere->radius = s.x();
      return sphere;
    }
    case Geometry::Mesh: {
      auto mesh = std::make_shared<urdf::Mesh>();
      mesh->filename = geometry.mesh_uri;
      mesh->scale = urdf::Vector3(s.x(), s.y(), s.z());
      return mesh;
    }
    case Geometry::Plane:
      break;
  }
  return nullptr;
}

}  // namespace bullet_sim
