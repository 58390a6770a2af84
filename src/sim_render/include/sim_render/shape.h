/// @file shape.h
/// @brief Description of one renderable primitive and its triangle mesh.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace sim_render {

/// Triangle mesh in the shape's local frame. Triangles wind counter-clockwise seen from
/// outside; `face_normals` holds one outward unit normal per triangle.
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Eigen::Vector3d> face_normals;
  /// Radius of a sphere about the local origin that holds every vertex.
  double bounding_radius_m = 0;
};

/// Kinds of shape: four primitives, and triangles given by the caller (a mesh file).
enum class ShapeKind { Box, Cylinder, Sphere, Plane, Mesh };

/// A primitive in its own frame, with its colour.
///
/// `size` follows the simulator's convention: box x y z; cylinder radius radius length (axis
/// along local z); sphere radius radius radius; plane size_x size_y 0, where size_x = size_y = 0
/// means an infinite plane. A plane faces `normal` (local frame, default +z) and is seen from
/// that side only. A mesh is `triangles` (their vertices and triangles; normals and radius
/// are recomputed) scaled by `size` per axis, seen from the side its triangles wind
/// counter-clockwise. Colours are linear 0..1; alpha is carried but surfaces are drawn opaque.
struct ShapeSpec {
  ShapeKind kind = ShapeKind::Box;
  Eigen::Vector3d size{1, 1, 1};
  Eigen::Vector3d normal{0, 0, 1};
  Eigen::Vector4f rgba{0.7f, 0.7f, 0.7f, 1.0f};
  std::shared_ptr<const Mesh> triangles;  ///< Mesh only, shared between shapes

  static ShapeSpec box(double x_m, double y_m, double z_m, const Eigen::Vector4f& rgba);
  static ShapeSpec cylinder(double radius_m, double length_m, const Eigen::Vector4f& rgba);
  static ShapeSpec sphere(double radius_m, const Eigen::Vector4f& rgba);
  /// size 0 x 0 gives an infinite plane.
  static ShapeSpec plane(double size_x_m, double size_y_m, const Eigen::Vector4f& rgba);
  /// `triangles` scaled by `scale` (x y z; a negative one mirrors).
  static ShapeSpec mesh(std::shared_ptr<const Mesh> triangles, const Eigen::Vector3d& scale,
                        const Eigen::Vector4f& rgba);
};

}  // namespace sim_render
