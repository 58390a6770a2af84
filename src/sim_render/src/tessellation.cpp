#include "sim_render/tessellation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sim_render {
namespace {

void requirePositive(Geometry::Kind kind, const char* what, double value) {
  if (!(std::isfinite(value) && value > 0.0)) {
    std::ostringstream msg;
    msg << kindName(kind) << " " << what << " must be finite and > 0, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

void requireAtLeast(const char* what, int value, int minimum) {
  if (value < minimum) {
    throw std::invalid_argument(std::string("tessellation ") + what + " must be >= " +
                                std::to_string(minimum) + ", got " + std::to_string(value));
  }
}

// Appends the triangle p, q, r (counter-clockwise seen from outside); degenerate ones are
// dropped so that every stored normal is a unit vector.
void addTriangle(Mesh& mesh, const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
  const Eigen::Vector3d n = (q - p).cross(r - p);
  const double norm = n.norm();
  if (norm < 1e-15) return;
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(p);
  mesh.vertices.push_back(q);
  mesh.vertices.push_back(r);
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.face_normals.push_back(n / norm);
}

void addQuad(Mesh& mesh, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
             const Eigen::Vector3d& p3) {
  addTriangle(mesh, p0, p1, p2);
  addTriangle(mesh, p0, p2, p3);
}

void buildBox(Mesh& mesh, const Eigen::Vector3d& size) {
  const Eigen::Vector3d h = 0.5 * size;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = sign;
      // u x v = n keeps the quad counter-clockwise seen from outside.
      Eigen::Vector3d u = Eigen::Vector3d::Zero();
      u[(axis + 1) % 3] = h[(axis + 1) % 3];
      const Eigen::Vector3d v = n.cross(u).normalized() * h[(axis + 2) % 3];
      const Eigen::Vector3d c = n * h[axis];
      addQuad(mesh, c - u - v, c + u - v, c + u + v, c - u + v);
    }
  }
}

void buildCylinder(Mesh& mesh, double radius, double length, int segments) {
  const double half = 0.5 * length;
  const Eigen::Vector3d top(0, 0, half), bottom(0, 0, -half);
  for (int k = 0; k < segments; ++k) {
    const double a0 = 2.0 * M_PI * k / segments, a1 = 2.0 * M_PI * (k + 1) / segments;
    const Eigen::Vector3d r0(radius * std::cos(a0), radius * std::sin(a0), 0);
    const Eigen::Vector3d r1(radius * std::cos(a1), radius * std::sin(a1), 0);
    addQuad(mesh, r0 + bottom, r1 + bottom, r1 + top, r0 + top);
    addTriangle(mesh, top, r0 + top, r1 + top);
    addTriangle(mesh, bottom, r1 + bottom, r0 + bottom);
  }
}

void buildSphere(Mesh& mesh, double radius, int rings, int segments) {
  auto point = [&](int ring, int segment) {
    const double theta = M_PI * ring / rings, phi = 2.0 * M_PI * segment / segments;
    return Eigen::Vector3d(radius * std::sin(theta) * std::cos(phi),
                           radius * std::sin(theta) * std::sin(phi), radius * std::cos(theta));
  };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      addQuad(mesh, point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
    }
  }
}

void buildPlane(Mesh& mesh, const ShapeSpec& spec, const TessellationOptions& options) {
  const bool infinite = spec.size.x() == 0.0 && spec.size.y() == 0.0;
  if (!infinite) {
    requirePositive(Geometry::Plane, "size x", spec.size.x());
    requirePositive(Geometry::Plane, "size y", spec.size.y());
  }
  const double n_norm = spec.normal.norm();
  if (!(std::isfinite(n_norm) && n_norm > 1e-12)) {
    std::ostringstream msg;
    msg << "plane normal must be a finite non-zero vector, got " << spec.normal.transpose();
    throw std::invalid_argument(msg.str());
  }
  const double hx = infinite ? options.infinite_plane_half_extent_m : 0.5 * spec.size.x();
  const double hy = infinite ? options.infinite_plane_half_extent_m : 0.5 * spec.size.y();
  // Columns u, v, n: a right-handed frame whose z is the normal (identity for n = +z).
  const Eigen::Vector3d n = spec.normal / n_norm;
  const Eigen::Vector3d helper = std::abs(n.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d u = helper.cross(n).normalized();
  Eigen::Matrix3d R;
  R << u, n.cross(u), n;
  addQuad(mesh, R * Eigen::Vector3d(-hx, -hy, 0), R * Eigen::Vector3d(hx, -hy, 0),
          R * Eigen::Vector3d(hx, hy, 0), R * Eigen::Vector3d(-hx, hy, 0));
}

// The caller's triangles scaled; a mirroring scale turns the winding round so that faces
// still point outwards. Degenerate triangles are dropped.
void buildScaledMesh(Mesh& mesh, const ShapeSpec& spec) {
  if (!spec.triangles || spec.triangles->triangles.empty()) {
    throw std::invalid_argument("mesh has no triangles");
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!std::isfinite(spec.size[axis]) || spec.size[axis] == 0.0) {
      std::ostringstream msg;
      msg << "mesh scale must be finite and non-zero, got " << spec.size.transpose();
      throw std::invalid_argument(msg.str());
    }
  }
  const Mesh& source = *spec.triangles;
  mesh.vertices.reserve(source.vertices.size());
  for (const Eigen::Vector3d& v : source.vertices) mesh.vertices.push_back(v.cwiseProduct(spec.size));
  const bool mirrored = spec.size.prod() < 0;
  for (std::array<std::uint32_t, 3> tri : source.triangles) {
    if (std::max({tri[0], tri[1], tri[2]}) >= mesh.vertices.size()) {
      throw std::invalid_argument("mesh triangle index " +
                                  std::to_string(std::max({tri[0], tri[1], tri[2]})) +
                                  " is beyond its " + std::to_string(mesh.vertices.size()) +
                                  " vertices");
    }
    if (mirrored) std::swap(tri[1], tri[2]);
    const Eigen::Vector3d& p = mesh.vertices[tri[0]];
    const Eigen::Vector3d n = (mesh.vertices[tri[1]] - p).cross(mesh.vertices[tri[2]] - p);
    if (n.norm() < 1e-15) continue;
    mesh.triangles.push_back(tri);
    mesh.face_normals.push_back(n.normalized());
  }
}

/// Gazebo Classic's "unit_box" texture coordinates: the whole image on every face, upright
/// on the side faces (v = 0 at the top), seen unmirrored from outside. `p` is the point
/// divided by the half sizes (each coordinate -1..1), `n` its face's outward normal.
Eigen::Vector2f boxUv(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  double u = 0, v = 0;
  if (n.x() > 0.5) {
    u = 1 + p.y(), v = 1 - p.z();
  } else if (n.x() < -0.5) {
    u = 1 - p.y(), v = 1 - p.z();
  } else if (n.y() > 0.5) {
    u = 1 - p.x(), v = 1 - p.z();
  } else if (n.y() < -0.5) {
    u = 1 + p.x(), v = 1 - p.z();
  } else if (n.z() > 0.5) {
    u = 1 - p.y(), v = 1 - p.x();
  } else {
    u = 1 - p.y(), v = 1 + p.x();
  }
  return Eigen::Vector2f(static_cast<float>(u / 2), static_cast<float>(v / 2));
}

/// Texture coordinates for the kinds that have them (see ShapeSpec); none for the others.
void addUvs(Mesh& mesh, const ShapeSpec& spec) {
  if (!spec.texture) return;
  if (spec.kind == Geometry::Box) {
    const Eigen::Vector3d half = 0.5 * spec.size;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      mesh.uvs.push_back(boxUv(mesh.vertices[i].cwiseQuotient(half), mesh.face_normals[i / 3]));
    }
  } else if (spec.kind == Geometry::Plane && spec.size.x() > 0 && spec.size.y() > 0) {
    // The quad's first edge runs along the plane's x axis, its last along its y axis.
    const Eigen::Vector3d x_axis = (mesh.vertices[1] - mesh.vertices[0]).normalized();
    const Eigen::Vector3d y_axis = (mesh.vertices[2] - mesh.vertices[1]).normalized();
    for (const Eigen::Vector3d& p : mesh.vertices) {
      mesh.uvs.emplace_back(static_cast<float>(0.5 + p.dot(x_axis) / spec.size.x()),
                            static_cast<float>(0.5 - p.dot(y_axis) / spec.size.y()));
    }
  } else if (spec.kind == Geometry::Mesh &&
             spec.triangles->uvs.size() == spec.triangles->vertices.size()) {
    mesh.uvs = spec.triangles->uvs;
  }
  for (Eigen::Vector2f& uv : mesh.uvs) uv = spec.uv_transform.apply(uv);
}

}  // namespace

Mesh tessellate(const ShapeSpec& spec, const TessellationOptions& options) {
  Mesh mesh;
  switch (spec.kind) {
    case Geometry::Box:
      requirePositive(spec.kind, "size x", spec.size.x());
      requirePositive(spec.kind, "size y", spec.size.y());
      requirePositive(spec.kind, "size z", spec.size.z());
      buildBox(mesh, spec.size);
      break;
    case Geometry::Cylinder:
      requirePositive(spec.kind, "radius", spec.size.x());
      requirePositive(spec.kind, "length", spec.size.z());
      requireAtLeast("cylinder_segments", options.cylinder_segments, 3);
      buildCylinder(mesh, spec.size.x(), spec.size.z(), options.cylinder_segments);
      break;
    case Geometry::Sphere:
      requirePositive(spec.kind, "radius", spec.size.x());
      requireAtLeast("sphere_rings", options.sphere_rings, 2);
      requireAtLeast("sphere_segments", options.sphere_segments, 3);
      buildSphere(mesh, spec.size.x(), options.sphere_rings, options.sphere_segments);
      break;
    case Geometry::Plane:
      buildPlane(mesh, spec, options);
      break;
    case Geometry::Mesh:
      buildScaledMesh(mesh, spec);
      break;
  }
  addUvs(mesh, spec);
  for (const Eigen::Vector3d& v : mesh.vertices) {
    mesh.bounding_radius_m = std::max(mesh.bounding_radius_m, v.norm());
  }
  return mesh;
}

ShapeSpec::ShapeSpec(const Geometry& geometry, const Eigen::Vector4f& colour)
    : Geometry(geometry), rgba(colour) {}

ShapeSpec ShapeSpec::box(double x_m, double y_m, double z_m, const Eigen::Vector4f& rgba) {
  return ShapeSpec(Geometry::box(x_m, y_m, z_m), rgba);
}

ShapeSpec ShapeSpec::cylinder(double radius_m, double length_m, const Eigen::Vector4f& rgba) {
  return ShapeSpec(Geometry::cylinder(radius_m, length_m), rgba);
}

ShapeSpec ShapeSpec::sphere(double radius_m, const Eigen::Vector4f& rgba) {
  return ShapeSpec(Geometry::sphere(radius_m), rgba);
}

ShapeSpec ShapeSpec::plane(double size_x_m, double size_y_m, const Eigen::Vector4f& rgba) {
  return ShapeSpec(Geometry::plane(size_x_m, size_y_m), rgba);
}

ShapeSpec ShapeSpec::mesh(std::shared_ptr<const sim_render::Mesh> triangles,
                          const Eigen::Vector3d& scale, const Eigen::Vector4f& rgba) {
  ShapeSpec s(Geometry::mesh("", scale), rgba);
  s.triangles = std::move(triangles);
  return s;
}

}  // namespace sim_render
