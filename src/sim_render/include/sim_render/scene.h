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

/// Light and sky. A surface of colour c whose outward normal n makes angle a with the
/// direction towards the light is drawn as c * (ambient + diffuse * max(0, cos a)),
/// clamped to 1 per channel. Pixels that show nothing get `background`.
struct Lighting {
  /// Direction the light travels (SDF <direction>), world frame; need not be unit length.
  Eigen::Vector3d direction{-0.5, 0.1, -0.9};
  Eigen::Vector3f diffuse{0.8f, 0.8f, 0.8f};
  Eigen::Vector3f ambient{0.4f, 0.4f, 0.4f};
  Eigen::Vector3f background{0.7f, 0.7f, 0.7f};
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
