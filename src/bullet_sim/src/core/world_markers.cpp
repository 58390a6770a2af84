#include "bullet_sim/world_markers.h"

#include "bullet_sim/mesh.h"
#include "robot_plan.h"

namespace bullet_sim {
namespace {

/// Extents of a shape as a marker's scale: the spec sizes are radii for round shapes.
Eigen::Vector3d roundScale(const Eigen::Vector3d& size, bool sphere) {
  const double d = 2.0 * size.x();
  return {d, d, sphere ? d : size.z()};
}

MarkerShape planeMarker(const StaticShape& s, const PlaneDrawing& planes) {
  MarkerShape m;
  m.type = MarkerShape::Cube;
  const bool infinite = !(s.size.x() > 0 && s.size.y() > 0);
  const double side = planes.infinite_plane_side_m;
  m.scale_m = {infinite ? side : s.size.x(), infinite ? side : s.size.y(), planes.thickness_m};
  // The box's z axis is the plane's normal; its centre sits below the plane so its top face
  // is plane_drop_m under the surface.
  const Eigen::Quaterniond T_geom_box =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), s.normal);
  const Eigen::Vector3d normal_world = s.pose.orientation * s.normal;
  m.pose.orientation = (s.pose.orientation * T_geom_box).normalized();
  m.pose.position =
      s.pose.position - normal_world * (planes.plane_drop_m + 0.5 * planes.thickness_m);
  return m;
}

/// A mesh file drawn at the mesh's scale.
MarkerShape meshMarker(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  MarkerShape m;
  m.type = MarkerShape::Mesh;
  m.scale_m = scale;
  m.mesh_resource = "file://" + mesh.path;
  return m;
}

MarkerShape shapeMarker(const StaticShape& s, const PlaneDrawing& planes) {
  MarkerShape m;
  switch (s.kind) {
    case StaticShape::Box:
      m.type = MarkerShape::Cube;
      m.scale_m = s.size;
      break;
    case StaticShape::Cylinder:
      m.type = MarkerShape::Cylinder;
      m.scale_m = roundScale(s.size, false);
      break;
    case StaticShape::Sphere:
      m.type = MarkerShape::Sphere;
      m.scale_m = roundScale(s.size, true);
      break;
    case StaticShape::Plane:
      m = planeMarker(s, planes);
      break;
    case StaticShape::Mesh:
      m = meshMarker(*s.mesh, s.size);
      break;
  }
  if (s.kind != StaticShape::Plane) m.pose = s.pose;
  return m;
}

}  // namespace

std::vector<MarkerShape> worldShapeMarkers(const WorldSpec& world, const PlaneDrawing& planes) {
  std::vector<MarkerShape> markers;
  std::map<std::string, int> next_id;
  for (const StaticShape& s : world.shapes) {
    if (s.kind == StaticShape::Mesh && !s.mesh) continue;  // unreadable: warned at load
    MarkerShape m = shapeMarker(s, planes);
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
    if (link == T_world_link.end() || (v.kind == VisualSpec::Mesh && !v.mesh)) continue;
    MarkerShape m;
    if (v.kind == VisualSpec::Mesh) {
      m = meshMarker(*v.mesh, v.size);
    } else {
      m.type = v.kind == VisualSpec::Box        ? MarkerShape::Cube
               : v.kind == VisualSpec::Cylinder ? MarkerShape::Cylinder
                                                : MarkerShape::Sphere;
      m.scale_m =
          v.kind == VisualSpec::Box ? v.size : roundScale(v.size, v.kind == VisualSpec::Sphere);
    }
    m.ns = model;
    m.id = static_cast<int>(i);
    m.pose = toPose3(link->second * toIsometry(v.pose_in_link));
    m.rgba = v.rgba;
    markers.push_back(m);
  }
  return markers;
}

MarkerChanges::MarkerChanges(double position_tolerance_m, double angle_tolerance_rad)
    : position_tolerance_m_(position_tolerance_m), angle_tolerance_rad_(angle_tolerance_rad) {}

bool MarkerChanges::same(const MarkerShape& a, const MarkerShape& b) const {
  return a.type == b.type && a.scale_m == b.scale_m && a.rgba == b.rgba &&
         a.mesh_resource == b.mesh_resource &&
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
