#include "bullet_sim/render/world_markers.h"

#include "bullet_sim/description/mesh.h"
#include "description/robot_plan.h"

namespace bullet_sim {
namespace {

/// A plane as a thin box: its z axis is the plane's normal, its top face plane_drop_m below
/// the surface.
void drawPlane(const Geometry& g, const PlaneDrawing& planes, MarkerShape* m) {
  m->type = MarkerShape::Cube;
  const bool infinite = !(g.size.x() > 0 && g.size.y() > 0);
  const double side = planes.infinite_plane_side_m;
  m->scale_m = {infinite ? side : g.size.x(), infinite ? side : g.size.y(), planes.thickness_m};
  const Eigen::Quaterniond T_geom_box =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), g.normal);
  const Eigen::Vector3d normal_world = m->pose.orientation * g.normal;
  m->pose.orientation = (m->pose.orientation * T_geom_box).normalized();
  m->pose.position -= normal_world * (planes.plane_drop_m + 0.5 * planes.thickness_m);
}

/// The marker of a geometry whose frame is at `pose` in the world; `mesh` holds a mesh's
/// triangles (the marker names its file). The one place a geometry kind becomes a marker
/// type: the spec sizes are radii for round shapes, a marker's scale their full extents.
MarkerShape markerOf(const Geometry& g, const TriangleMesh* mesh, const TextureRef& texture,
                     const Pose3& pose, const PlaneDrawing& planes) {
  MarkerShape m;
  m.pose = pose;
  const bool finite_plane = g.kind == Geometry::Plane && g.size.x() > 0 && g.size.y() > 0;
  if (!texture.path.empty() && (g.kind == Geometry::Box || finite_plane)) {
    m.type = MarkerShape::Mesh;
    m.scale_m = Eigen::Vector3d::Ones();
    m.textured_geometry = g;
    m.texture = texture;
    if (finite_plane) m.pose.position -= (pose.orientation * g.normal.normalized()) * planes.plane_drop_m;
    return m;
  }
  const double diameter = 2.0 * g.size.x();
  switch (g.kind) {
    case Geometry::Box:
      m.type = MarkerShape::Cube;
      m.scale_m = g.size;
      break;
    case Geometry::Cylinder:
      m.type = MarkerShape::Cylinder;
      m.scale_m = {diameter, diameter, g.size.z()};
      break;
    case Geometry::Sphere:
      m.type = MarkerShape::Sphere;
      m.scale_m = Eigen::Vector3d::Constant(diameter);
      break;
    case Geometry::Plane:
      drawPlane(g, planes, &m);
      break;
    case Geometry::Mesh:
      m.type = MarkerShape::Mesh;
      m.scale_m = g.size;
      m.mesh_resource = "file://" + mesh->path;
      for (const MeshPart& part : mesh->parts) m.embedded_materials |= !part.texture_path.empty();
      break;
  }
  return m;
}

}  // namespace

std::vector<MarkerShape> worldShapeMarkers(const WorldSpec& world, const PlaneDrawing& planes) {
  std::vector<MarkerShape> markers;
  std::map<std::string, int> next_id;
  for (const StaticShape& s : world.shapes) {
    if (s.kind == Geometry::Mesh && !s.mesh) continue;  // unreadable: warned at load
    MarkerShape m = markerOf(s, s.mesh.get(), s.texture, s.pose, planes);
    m.ns = s.model;
    m.id = next_id[s.model]++;
    m.rgba = s.rgba;
    markers.push_back(m);
  }
  return markers;
}

std::vector<MarkerShape> modelMarkers(const std::string& model, const RobotSpec& spec,
                                      const std::vector<LinkPose>& link_poses) {
  std::map<std::string, Eigen::Isometry3d> T_world_link;
  for (const LinkPose& lp : link_poses) T_world_link[lp.link] = toIsometry(lp.pose);
  std::vector<MarkerShape> markers;
  for (size_t i = 0; i < spec.visuals.size(); ++i) {
    const VisualSpec& v = spec.visuals[i];
    const auto link = T_world_link.find(v.link);
    if (link == T_world_link.end() || (v.kind == Geometry::Mesh && !v.mesh)) continue;
    const Pose3 pose = toPose3(link->second * toIsometry(v.pose_in_link));
    MarkerShape m = markerOf(v, v.mesh.get(), v.texture, pose, PlaneDrawing());
    m.ns = model;
    m.id = static_cast<int>(i);
    m.rgba = v.rgba;
    markers.push_back(m);
  }
  return markers;
}

MarkerChanges::MarkerChanges(double position_tolerance_m, double angle_tolerance_rad)
    : position_tolerance_m_(position_tolerance_m), angle_tolerance_rad_(angle_tolerance_rad) {}

bool MarkerChanges::same(const MarkerShape& a, const MarkerShape& b) const {
  return a.type == b.type && a.scale_m == b.scale_m && a.rgba == b.rgba &&
         a.mesh_resource == b.mesh_resource && a.texture.path == b.texture.path &&
         (a.pose.position - b.pose.position).norm() <= position_tolerance_m_ &&
         a.pose.orientation.angularDistance(b.pose.orientation) <= angle_tolerance_rad_;
}

std::vector<MarkerShape> MarkerChanges::update(const std::vector<MarkerShape>& current) {
  std::vector<MarkerShape> changed;
  for (const MarkerShape& m : current) {
    const auto key = std::make_pair(m.ns, m.id);
    const auto last = published_.find(key);
    if (last != published_.end() && same(last->second, m)) continue;
    published_[key] = m;
    changed.push_back(m);
  }
  return changed;
}

}  // namespace bullet_sim
