#ifndef BULLET_SIM_WORLD_SPEC_H
#define BULLET_SIM_WORLD_SPEC_H

#include <memory>
#include <string>
#include <vector>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// One static collision/visual shape of the world: its geometry (a mesh's `mesh_uri` is the
/// SDF <uri> as written), where it stands and what it looks like.
struct StaticShape : Geometry {
  std::string model, link;
  std::string name;                  ///< the <collision> or <visual> name
  Pose3 pose;                        ///< world pose of the geometry
  /// Mesh only: its triangles (collision: the triangle mesh itself, as the shape is static)
  std::shared_ptr<const TriangleMesh> mesh;
  /// The material colour; a mesh part with a colour of its own in the file keeps that.
  Eigen::Vector4f rgba{0.7f, 0.7f, 0.7f, 1.0f};
  TextureRef texture;  ///< a Gazebo material script's texture (mesh files carry their own)
  bool collides = true;              ///< false for visual-only geometry
  /// Collision only: the friction coefficient of its <surface> (SurfaceParams::isotropicMu;
  /// 1, Gazebo's default, where the file gives none)
  double friction = 1.0;
};

/// A movable (non-static) model of the world: simulated as a robot of the same name,
/// with its links, inertials and joints.
struct WorldModel {
  std::string name;
  RobotSpec spec;
  Pose3 pose;  ///< the model frame in the world (its <state> pose when the world has one)
};

/// A world read from SDF. Static models become shapes, movable ones `models`; the poses
/// of a saved <state> are applied, as Gazebo does when it loads a saved world.
/// A static model of the world (its shapes are in WorldSpec::shapes) and where it stands.
struct StaticModel {
  std::string name;
  Pose3 pose;  ///< the model frame in the world
};

/// A <light> of the world, as Gazebo (OGRE) lights the scene with it.
struct LightSpec {
  std::string name, type = "point";  ///< "point", "directional" or "spot"
  Pose3 pose;                        ///< world pose of the light
  Eigen::Vector3d direction{0, 0, -1};  ///< world frame, unit (directional and spot)
  Eigen::Vector4f diffuse{1, 1, 1, 1}, specular{0.1f, 0.1f, 0.1f, 1};
  /// <attenuation>: the light reaches `range_m`; its intensity at distance d is
  /// 1 / (constant + linear d + quadratic d^2)
  double range_m = 10, constant = 1, linear = 1, quadratic = 0;
  double spot_inner_rad = 0, spot_outer_rad = 0, spot_falloff = 0;  ///< spot only
  bool cast_shadows = false;
};

struct WorldSpec {
  std::string name;
  std::vector<StaticShape> shapes;
  std::vector<StaticModel> static_models;  ///< top-level static models, in file order
  std::vector<WorldModel> models;
  Eigen::Vector3d gravity{0, 0, -9.8};
  double max_step_size_s = 0.001;
  /// The direction of the world's first directional light (the sun), world frame
  Eigen::Vector3d light_direction{-0.5, 0.1, -0.9};
  std::vector<LightSpec> lights;  ///< every <light> of the world, in file order
  Eigen::Vector4f ambient{0.4f, 0.4f, 0.4f, 1.0f};
  std::vector<std::string> warnings;
};

/// Loads an SDF world file with libsdformat; URIs in it (includes, meshes) are looked
/// up through `resolver`, relative ones from the file's folder. `<include>`d models come
/// from the resolver's model folders (model.config picks the SDF file); `sun` and
/// `ground_plane` are built in when no folder provides them.
/// @throws LoadError naming the path (and for a missing model, the URI and folders searched).
WorldSpec loadWorldFile(const std::string& path, const UriResolver& resolver);
/// As above, but the XML and libsdformat documents the world was read from are handed over
/// in `documents` rather than freed before the spec is returned: freeing them is about a
/// sixth of the load, which a caller in a hurry does later or on another thread. The spec
/// refers to nothing in them.
WorldSpec loadWorldFile(const std::string& path, const UriResolver& resolver,
                        std::shared_ptr<const void>* documents);
/// As above, with the resource paths of the environment (GAZEBO_MODEL_PATH, ROS_PACKAGE_PATH).
WorldSpec loadWorldFile(const std::string& path);
/// Loads an SDF world from a string. @throws LoadError naming source_name.
WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name,
                          const UriResolver& resolver);
WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name);

}  // namespace bullet_sim

#endif  // BULLET_SIM_WORLD_SPEC_H
