/// @file geometry.h
/// @brief The one description of a shape's geometry, shared by the robot and world loaders,
/// the physics and the renderer.
#pragma once

#include <Eigen/Core>

#include <string>

namespace sim_render {

/// What a shape is, whatever it is used for. The simulator's URDF visuals, SDF world shapes
/// and collision shapes, and this package's ShapeSpec each are a Geometry plus what their
/// use adds (a pose, a colour, the mesh's triangles), so that a kind read by a loader
/// reaches physics and rendering unchanged, with no second enum to keep in step.
///
/// `size` by kind: box x y z; cylinder radius radius length (axis along local z); sphere
/// radius radius radius; plane size_x size_y 0, where 0 x 0 is an infinite plane facing
/// `normal` (geometry frame, default +z); mesh: its scale x y z (a negative one mirrors)
/// of the file `mesh_uri` names, as written in the description.
struct Geometry {
  enum Kind { Box, Cylinder, Sphere, Plane, Mesh };

  Kind kind = Box;
  Eigen::Vector3d size{0, 0, 0};
  Eigen::Vector3d normal{0, 0, 1};
  std::string mesh_uri;

  static Geometry box(double x_m, double y_m, double z_m) {
    return make(Box, Eigen::Vector3d(x_m, y_m, z_m));
  }
  static Geometry cylinder(double radius_m, double length_m) {
    return make(Cylinder, Eigen::Vector3d(radius_m, radius_m, length_m));
  }
  static Geometry sphere(double radius_m) {
    return make(Sphere, Eigen::Vector3d::Constant(radius_m));
  }
  /// size 0 x 0 gives an infinite plane.
  static Geometry plane(double size_x_m, double size_y_m,
                        const Eigen::Vector3d& normal = Eigen::Vector3d::UnitZ()) {
    Geometry g = make(Plane, Eigen::Vector3d(size_x_m, size_y_m, 0));
    g.normal = normal;
    return g;
  }
  static Geometry mesh(const std::string& uri, const Eigen::Vector3d& scale) {
    Geometry g = make(Mesh, scale);
    g.mesh_uri = uri;
    return g;
  }

  /// The geometry part of a shape that is a Geometry plus more: `shape.geometry() = g`
  /// sets what `g` describes and leaves the rest of `shape` as it was.
  Geometry& geometry() { return *this; }
  const Geometry& geometry() const { return *this; }

 private:
  static Geometry make(Kind kind, const Eigen::Vector3d& size) {
    Geometry g;
    g.kind = kind;
    g.size = size;
    return g;
  }
};

/// "box", "cylinder", "sphere", "plane" or "mesh", for messages.
inline const char* kindName(Geometry::Kind kind) {
  switch (kind) {
    case Geometry::Box: return "box";
    case Geometry::Cylinder: return "cylinder";
    case Geometry::Sphere: return "sphere";
    case Geometry::Plane: return "plane";
    case Geometry::Mesh: return "mesh";
  }
  return "unknown";
}

}  // namespace sim_render
