/// @file scene.h
/// @brief The set of shapes, the light and the sky that a Renderer draws.
#pragma once

#include "sim_render/shape.h"
#include "sim_render/tessellation.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sim_render {

/// Handle of a shape in a Scene; never reused within one Scene.
using ShapeId = std::uint32_t;

/// A light besides the sun, as OGRE's per-pixel lighting (Gazebo's RTShader "pixel"
/// model) adds it. At a surface point p with outward unit normal n, L the unit vector
/// from p towards the light and d its distance, a point or spot light adds
/// `diffuse * max(0, n . L) * attenuation * spot` to the light factor, where
/// attenuation = 1 / (constant + linear d + quadratic d^2) for d <= range_m, 0 beyond, and
/// for a spot light, with rho the cosine between `direction` and the ray from the light to
/// p, spot = clamp((rho - cos(outer / 2)) / (cos(inner / 2) - cos(outer / 2)), 0, 1) ^ falloff
/// (1 for a point light). A directional light adds `diffuse * max(0, n . -direction)`.
struct LocalLight {
  enum class Kind { Point, Spot, Directional };
  Kind kind = Kind::Point;
  Eigen::Vector3d position{0, 0, 0};    ///< world frame (point, spot)
  Eigen::Vector3d direction{0, 0, -1};  ///< where the light travels, world frame, non-zero
  Eigen::Vector3f diffuse{1.0f, 1.0f, 1.0f};
  double range_m = 10;
  double constant = 1, linear = 0, quadratic = 0;
  /// Spot only: the full angles of the inner and outer cones (OGRE's setSpotlightRange),
  /// and the exponent between them. A falloff of 0 makes the outer cone a hard edge.
  double spot_inner_rad = 0, spot_outer_rad = 0, spot_falloff = 1;
};

/// Light and sky. A surface of colour c whose outward normal n makes angle a with the
/// direction towards the sun is drawn as c * (ambient + diffuse * max(0, cos a) + the
/// `lights`' terms (see LocalLight)), clamped to 1 per channel. Pixels that show nothing
/// get `background`.
struct Lighting {
  /// Direction the sun's light travels (SDF <direction>), world frame; need not be unit length.
  Eigen::Vector3d direction{-0.5, 0.1, -0.9};
  Eigen::Vector3f diffuse{0.8f, 0.8f, 0.8f};
  Eigen::Vector3f ambient{0.4f, 0.4f, 0.4f};
  Eigen::Vector3f background{0.7f, 0.7f, 0.7f};
  /// Point, spot and further directional lights. Surfaces a point or spot light reaches
  /// are lit per pixel; the others cost what they did.
  std::vector<LocalLight> lights;
};

/// One shape as the renderer sees it: its mesh (built once) and its current world pose.
struct SceneShape {
  ShapeId id = 0;
  ShapeSpec spec;
  Mesh mesh;
  Eigen::Isometry3d T_world_shape = Eigen::Isometry3d::Identity();
};

/// Shapes with world poses. Adding a shape tessellates it once; moving it only stores the
/// new pose, so robot links can be updated every frame at no cost.
class Scene {
 public:
  explicit Scene(const TessellationOptions& options = {});

  /// Adds a shape; throws std::invalid_argument (see tessellate()) for a bad size.
  ShapeId add(const ShapeSpec& spec, const Eigen::Isometry3d& T_world_shape);
  /// Moves a shape; throws std::out_of_range naming the id when it is unknown.
  void setPose(ShapeId id, const Eigen::Isometry3d& T_world_shape);
  /// Recolours a shape; throws std::out_of_range naming the id when it is unknown.
  void setColor(ShapeId id, const Eigen::Vector4f& rgba);
  /// Removes a shape; returns false when the id is unknown.
  bool remove(ShapeId id);
  bool contains(ShapeId id) const { return index_.count(id) != 0; }
  void clear();

  std::size_t size() const { return shapes_.size(); }
  const std::vector<SceneShape>& shapes() const { return shapes_; }
  const SceneShape& shape(ShapeId id) const;

  Lighting& lighting() { return lighting_; }
  const Lighting& lighting() const { return lighting_; }

 private:
  std::size_t slotOf(ShapeId id) const;
  SceneShape& mutableShape(ShapeId id);

  TessellationOptions options_;
  Lighting lighting_;
  std::vector<SceneShape> shapes_;
  std::unordered_map<ShapeId, std::size_t> index_;
  ShapeId next_id_ = 1;
};

}  // namespace sim_render
