#ifndef BULLET_SIM_CORE_STATIC_LINK_SHAPES_H
#define BULLET_SIM_CORE_STATIC_LINK_SHAPES_H

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/description/world_spec.h"
#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// The shapes of the links of a world's static models: each collision a shape, each
/// visual the colour (and texture) of the collision it equals, or a visual-only shape.
class StaticLinkShapes {
 public:
  /// `source` names the world file in messages and is the folder of relative mesh files.
  StaticLinkShapes(std::string source, const UriResolver& resolver)
      : source_(std::move(source)), resolver_(resolver) {}

  /// Adds the collisions and visuals of `link` of static model `model` (its scoped name),
  /// posed at T_world_link, to spec->shapes.
  /// @throws LoadError for an unsupported geometry, a bad size or scale, or a collision mesh
  /// that is found but cannot be read.
  void read(const std::string& model, const SdfLink& link, const Eigen::Isometry3d& T_world_link,
            WorldSpec* spec);

  /// Warnings about meshes not found or not drawn, in the order met.
  const std::vector<std::string>& meshWarnings() const { return mesh_warnings_; }

 private:
  void addCollision(const std::string& model, const SdfLink& link, const SdfCollision& col,
                    const Eigen::Isometry3d& T_world_link, WorldSpec* spec);
  void addVisual(const std::string& model, const SdfLink& link, const SdfVisual& vis,
                 const Eigen::Isometry3d& T_world_link, WorldSpec* spec);
  /// The shape of a collision or visual `name` of `link`, its size checked; `where` is
  /// set to the element's name for messages. `origin` is where the element was read (the
  /// folder of relative mesh files).
  StaticShape elementShape(const std::string& model, const SdfLink& link,
                           const std::string& name, const SdfGeometry& geometry,
                           const SdfOrigin& origin, const Eigen::Isometry3d& T_world_element,
                           bool collides, std::string* where);
  /// A mesh's triangles: its file resolved from the folder of the SDF file that names it.
  /// A collision mesh that cannot be read is an error, a visual one a warning (not drawn).
  void meshShape(const std::string& model, const SdfLink& link, const SdfGeometry& geometry,
                 const SdfOrigin& origin, bool collides, StaticShape* s);

  std::string source_;
  const UriResolver& resolver_;
  std::vector<std::string> mesh_warnings_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_STATIC_LINK_SHAPES_H
