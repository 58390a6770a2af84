/// @file tessellation.h
/// @brief Turns a ShapeSpec into a triangle mesh in the shape's local frame.
#pragma once

#include "sim_render/shape.h"

namespace sim_render {

/// How finely curved shapes are cut into triangles.
struct TessellationOptions {
  int cylinder_segments = 24;  ///< facets around a cylinder
  int sphere_rings = 12;       ///< latitude bands of a sphere
  int sphere_segments = 24;    ///< longitude slices of a sphere
  /// Half extent used for an infinite plane; larger than any sensible far clip distance.
  double infinite_plane_half_extent_m = 1e5;
};

/// Builds the mesh of `spec` (for Geometry::Mesh: its triangles scaled). Throws
/// std::invalid_argument naming the bad value when a size is not finite or not positive
/// (planes: negative, or only one side zero; meshes: a scale zero or not finite, no
/// triangles, an index beyond the vertices), or when the options ask for too few segments.
Mesh tessellate(const ShapeSpec& spec, const TessellationOptions& options = {});

}  // namespace sim_render
