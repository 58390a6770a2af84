#ifndef BULLET_SIM_WORLD_MARKERS_H
#define BULLET_SIM_WORLD_MARKERS_H

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/sensors/sensor_data.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// One drawable shape of the world, as a 3D viewer's marker wants it (the node turns it
/// into a visualization_msgs/Marker; nothing here knows ROS).
struct MarkerShape {
  enum Type { Cube, Cylinder, Sphere, Mesh };
  std::string ns;                 ///< the model the shape belongs to
  int id = 0;                     ///< unique within ns, stable from one update to the next
  Type type = Cube;
  Pose3 pose;                     ///< centre of the shape in the world frame
  Eigen::Vector3d scale_m{0, 0, 0};  ///< full extents: box x y z; cylinder and sphere diameters
                                     ///< in x y, length (or diameter) in z
  Eigen::Vector4f rgba{0.7f, 0.7f, 0.7f, 1.0f};
  std::string mesh_resource;  ///< Mesh only: "file://" and the mesh file's path; scale_m is
                              ///< the mesh's scale
  /// Mesh only: the file has textures of its own, which a viewer should draw (RViz:
  /// mesh_use_embedded_materials with the colour left 0 0 0 0).
  bool embedded_materials = false;
  /// A box or finite plane painted by a material script: its geometry and texture. Its type
  /// is Mesh, with no mesh_resource yet: the publisher writes a textured mesh of it
  /// (writeTexturedMesh in textured_mesh.h) and names that file; pose is the geometry's
  /// frame, scale_m 1 1 1.
  std::optional<Geometry> textured_geometry;
  TextureRef texture;
};

/// How planes are drawn: a plane is a box this thin, its top face lying `plane_drop_m` below
/// the plane so that a viewer's grid at the same height stays visible; a plane without a size
/// (infinite) becomes a square of side `infinite_plane_side_m`.
struct PlaneDrawing {
  double thickness_m = 0.002;
  double plane_drop_m = 0.002;
  double infinite_plane_side_m = 100.0;
};

/// The static shapes of a world as markers, one per shape, in the order of `world.shapes`,
/// with ns = the model's name and ids counting from 0 in each model (mesh visuals that could
/// not be read are left out). The world loader
/// keeps a visual equal to its collision as one shape, so each wall is one marker.
std::vector<MarkerShape> worldShapeMarkers(const WorldSpec& world,
                                           const PlaneDrawing& planes = PlaneDrawing());

/// The visuals of a movable model (a dynamic world model) at its current link poses, as
/// Simulation::linkPoses returns them. Visuals of links missing from `link_poses` and mesh
/// visuals that could not be read are left out. ns = `model`, ids count from 0 in the order of `spec.visuals`.
std::vector<MarkerShape> modelMarkers(const std::string& model, const RobotSpec& spec,
                                      const std::vector<LinkPose>& link_poses);

/// Remembers what was last published and says which markers differ from it, so that a
/// moving model is republished and a resting one costs nothing.
class MarkerChanges {
 public:
  /// @param position_tolerance_m, angle_tolerance_rad  smaller motions are not a change
  MarkerChanges(double position_tolerance_m, double angle_tolerance_rad);

  /// The markers of `current` that are new or moved, changed size or colour since the last
  /// call; they are remembered as published.
  std::vector<MarkerShape> update(const std::vector<MarkerShape>& current);

 private:
  bool same(const MarkerShape& a, const MarkerShape& b) const;

  double position_tolerance_m_, angle_tolerance_rad_;
  std::map<std::pair<std::string, int>, MarkerShape> published_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_WORLD_MARKERS_H
