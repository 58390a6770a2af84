#include "description/sdf/static_link_shapes.h"

#include <filesystem>
#include <sstream>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/material/visual_appearance.h"
#include "description/robot_plan.h"
#include "description/sdf/sdf_surface.h"
#include "description/sdf/sdf_util.h"

namespace bullet_sim {
namespace {

/// A visual equal to a collision shape of the same link colours it instead
/// of adding a second, visual-only shape.
void mergeVisual(const StaticShape& visual, WorldSpec* spec) {
  for (StaticShape& s : spec->shapes) {
    if (s.collides && s.model == visual.model && s.link == visual.link &&
        s.kind == visual.kind && s.mesh == visual.mesh && s.size.isApprox(visual.size, 1e-9) &&
        (s.pose.position - visual.pose.position).norm() < 1e-9 &&
        s.pose.orientation.angularDistance(visual.pose.orientation) < 1e-9) {
      s.rgba = visual.rgba;
      s.texture = visual.texture;
      return;
    }
  }
  spec->shapes.push_back(visual);
}

/// The folder of the file that defines a mesh, "" when that is no file.
std::string meshBaseDir(const SdfOrigin& origin) {
  std::error_code ec;
  return std::filesystem::is_regular_file(origin.file, ec)
             ? std::filesystem::path(origin.file).parent_path().string()
             : "";
}

}  // namespace

StaticShape StaticLinkShapes::elementShape(const std::string& model, const SdfLink& link,
                                           const std::string& name, const SdfGeometry& geometry,
                                           const SdfOrigin& origin,
                                           const Eigen::Isometry3d& T_world_element,
                                           bool collides, std::string* where) {
  *where = source_ + ": model '" + model + "' link '" + link.name + "' " +
           (collides ? "collision" : "visual") + " '" + name + "'";
  checkGeometrySize(geometry, *where);
  StaticShape s;
  s.model = model;
  s.link = link.name;
  s.name = name;
  s.pose = toPose3(T_world_element);
  s.collides = collides;
  if (!geometry.shape) {
    throw LoadError(source_ + ": model '" + model + "' link '" + link.name + "' " +
                    (collides ? "collision" : "visual") + ": geometry type '" + geometry.type +
                    "' is not supported (box, cylinder, sphere, plane, mesh are)");
  }
  s.geometry() = *geometry.shape;
  if (s.kind == Geometry::Mesh) meshShape(model, link, geometry, origin, collides, &s);
  return s;
}

void StaticLinkShapes::read(const std::string& model, const SdfLink& link,
                            const Eigen::Isometry3d& T_world_link, WorldSpec* spec) {
  for (const SdfCollision& c : link.collisions) addCollision(model, link, c, T_world_link, spec);
  for (const SdfVisual& v : link.visuals) addVisual(model, link, v, T_world_link, spec);
}

void StaticLinkShapes::addCollision(const std::string& model, const SdfLink& link,
                                    const SdfCollision& col,
                                    const Eigen::Isometry3d& T_world_link, WorldSpec* spec) {
  std::string where;
  StaticShape s = elementShape(model, link, col.name, col.geometry, col.origin,
                               T_world_link * col.T_link_collision, true, &where);
  if (s.kind == Geometry::Mesh && !s.mesh) return;  // not found: warned, left out
  SurfaceParams surface;
  readOdeFriction(col, where, &surface);
  s.friction = surface.isotropicMu();
  spec->shapes.push_back(std::move(s));
}

/// A visual colours the collision shape it equals, or is a visual-only shape.
void StaticLinkShapes::addVisual(const std::string& model, const SdfLink& link,
                                 const SdfVisual& vis, const Eigen::Isometry3d& T_world_link,
                                 WorldSpec* spec) {
  std::string where;
  StaticShape s = elementShape(model, link, vis.name, vis.geometry, vis.origin,
                               T_world_link * vis.T_link_visual, false, &where);
  const Appearance look = visualAppearance(vis, where, resolver_, &spec->warnings);
  s.rgba = look.rgba;
  s.texture = look.texture;
  mergeVisual(s, spec);
}

void StaticLinkShapes::meshShape(const std::string& model, const SdfLink& link,
                                 const SdfGeometry& geometry, const SdfOrigin& origin,
                                 bool collides, StaticShape* s) {
  const std::string where = source_ + ": model '" + model + "' link '" + link.name + "' " +
                            (collides ? "collision" : "visual") + " mesh '" + s->mesh_uri + "'";
  if (!s->size.allFinite() || (s->size.array() == 0).any()) {
    std::ostringstream text;
    text << s->size.x() << " " << s->size.y() << " " << s->size.z();
    throw LoadError(where + ": <scale> '" + text.str() + "' must be finite and non-zero");
  }
  std::string reason;
  s->mesh = loadMeshUri(resolver_, s->mesh_uri, meshBaseDir(origin), &reason);
  // Gazebo goes on without a mesh it cannot find (a model of its online database that is
  // not installed, as turtlebot3_house's mailbox): so does the world, saying so. A file
  // that is found but cannot be read is an error.
  if (!s->mesh && collides && reason.rfind("file not found", 0) != 0) {
    throw LoadError(where + ": " + reason);
  }
  if (!s->mesh) {
    mesh_warnings_.push_back(where + ": " + reason +
                             (collides ? ": left out (nothing collides with it)" : ": not drawn"));
  }
  if (!geometry.submesh.empty()) {
    mesh_warnings_.push_back(where + ": <submesh> '" + geometry.submesh +
                             "' is not supported: the whole mesh is used");
  }
}

}  // namespace bullet_sim
