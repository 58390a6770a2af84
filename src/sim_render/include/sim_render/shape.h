/// @file shape.h
/// @brief Description of one renderable primitive and its triangle mesh.
#pragma once

#include "sim_render/geometry.h"
#include "sim_render/texture.h"

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
  /// Texture coordinates, one per vertex, or none (the shape is then drawn in flat colour).
  std::vector<Eigen::Vector2f> uvs;
  /// Radius of a sphere about the local origin that holds every vertex.
  double bounding_radius_m = 0;
};

/// A Geometry in its own frame, with its colour, as the renderer draws it.
///
/// A plane is seen from the side its `normal` faces only. A mesh is `triangles` (their
/// vertices and triangles; normals and radius are recomputed) scaled by `size` per axis, seen
/// from the side its triangles wind counter-clockwise; its `mesh_uri` is not read here.
/// Colours are linear 0..1; alpha is carried but surfaces are drawn opaque.
///
/// With a `texture`, each pixel is the texel times `rgba` (OGRE's default modulation: keep
/// `rgba` white for the texture's own colours), lit as a flat surface is. Texture
/// coordinates are Gazebo Classic's: a box gets the whole image on each face (its
/// MeshManager "unit_box"), a finite plane the whole image once, +x to the right and +y up
/// (its "unit_plane"), a mesh the coordinates of its file (Mesh::uvs, through
/// `uv_transform`). Cylinders, spheres, infinite planes and meshes without coordinates are
/// drawn in `rgba` times the texture's mean colour.
struct ShapeSpec : Geometry {
  Eigen::Vector4f rgba{0.7f, 0.7f, 0.7f, 1.0f};
  std::shared_ptr<const Texture> texture;
  UvTransform uv_transform;
  /// Mesh only, shared between shapes. (Named with its namespace: in here `Mesh` is the
  /// inherited Geometry::Mesh kind.)
  std::shared_ptr<const sim_render::Mesh> triangles;

  ShapeSpec() = default;
  /// A box, cylinder, sphere or plane (a mesh also needs its triangles: see mesh()).
  ShapeSpec(const Geometry& geometry, const Eigen::Vector4f& rgba);

  static ShapeSpec box(double x_m, double y_m, double z_m, const Eigen::Vector4f& rgba);
  static ShapeSpec cylinder(double radius_m, double length_m, const Eigen::Vector4f& rgba);
  static ShapeSpec sphere(double radius_m, const Eigen::Vector4f& rgba);
  /// size 0 x 0 gives an infinite plane.
  static ShapeSpec plane(double size_x_m, double size_y_m, const Eigen::Vector4f& rgba);
  /// `triangles` scaled by `scale` (x y z; a negative one mirrors).
  static ShapeSpec mesh(std::shared_ptr<const sim_render::Mesh> triangles,
                        const Eigen::Vector3d& scale, const Eigen::Vector4f& rgba);
};

}  // namespace sim_render
