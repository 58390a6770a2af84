#include "description/sdf/static_link_shapes.h"

#include <filesystem>
#include <sstream>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/material/visual_appearance.h"
#include "description/robot_plan.h"
#include "description/sdf/sdf_surface.h"
#include "description/sdf/sdf_urdf_convert.h"
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

/// The folder of the file that defines a mesh (`source` when libsdformat does not say),
/// "" when that is no file.
std::string meshBaseDir(const sdf::Mesh& mesh, const std::string& source) {
  const std::string defined_in = mesh.FilePath().empty() ? source : mesh.FilePath();
  std::error_code ec;
  return std::filesystem::is_regular_file(defined_in, ec)
             ? std::filesystem::path(defined_in).parent_path().string()
             : "";
}

}  // namespace

template <class Element>
StaticShape StaticLinkShapes::elementShape(const std::string& model, const sdf::Link& link,
                                           const Element& element,
                                           const Eigen::Isometry3d& T_world_link, bool collides,
                                           std::string* where) {
  *where = source_ + ": model '" + model + "' link '" + link.Name() + "' " +
           (collides ? "collision" : "visual") + " '" + element.Name() + "'";
  checkGeometrySize(*element.Geom(), *where);
  return shape(model, link, *element.Geom(), T_world_link * sdfToIsometry(poseInParent(element)),
               collides);
}

void StaticLinkShapes::read(const std::string& model, const sdf::Link& link,
                            const Eigen::Isometry3d& T_world_link, WorldSpec* spec) {
  for (uint64_t c = 0; c < link.CollisionCount(); ++c) {
    addCollision(model, link, *link.CollisionByIndex(c), T_world_link, spec);
  }
  for (uint64_t v = 0; v < link.VisualCount(); ++v) {
    addVisual(model, link, *link.VisualByIndex(v), T_world_link, spec);
  }
}

void StaticLinkShapes::addCollision(const std::string& model, const sdf::Link& link,
                                    const sdf::Collision& col,
                                    const Eigen::Isometry3d& T_world_link, WorldSpec* spec) {
  std::string where;
  StaticShape s = elementShape(model, link, col, T_world_link, true, &where);
  if (s.kind == Geometry::Mesh && !s.mesh) return;  // not found: warned, left out
  SurfaceParams surface;
  readOdeFriction(col, where, &surface);
  s.friction = surface.isotropicMu();
  spec->shapes.push_back(std::move(s));
}

/// A visual colours the collision shape it equals, or is a visual-only shape.
void StaticLinkShapes::addVisual(const std::string& model, const sdf::Link& link,
                                 const sdf::Visual& vis, const Eigen::Isometry3d& T_world_link,
                                 WorldSpec* spec) {
  std::string where;
  StaticShape s = elementShape(model, link, vis, T_world_link, false, &where);
  const Appearance look = visualAppearance(vis, where, source_, resolver_, &spec->warnings);
  s.rgba = look.rgba;
  s.texture = look.texture;
  mergeVisual(s, spec);
}

StaticShape StaticLinkShapes::shape(const std::string& model, const sdf::Link& link,
                                    const sdf::Geometry& geom, const Eigen::Isometry3d& pose,
                                    bool collides) {
  StaticShape s;
  s.model = model;
  s.link = link.Name();
  s.pose = toPose3(pose);
  s.collides = collides;
  const std::optional<Geometry> geometry = geometryOf(geom);
  if (!geometry) {
    throw LoadError(source_ + ": model '" + model + "' link '" + link.Name() + "' " +
                    (collides ? "collision" : "visual") + ": geometry type '" +
                    geometryName(geom.Type()) +
                    "' is not supported (box, cylinder, sphere, plane, mesh are)");
  }
  s.geometry() = *geometry;
  if (s.kind == Geometry::Mesh) meshShape(model, link, *geom.MeshShape(), collides, &s);
  return s;
}

void StaticLinkShapes::meshShape(const std::string& model, const sdf::Link& link,
                                 const sdf::Mesh& mesh, bool collides, StaticShape* s) {
  const std::string where = source_ + ": model '" + model + "' link '" + link.Name() + "' " +
                            (collides ? "collision" : "visual") + " mesh '" + mesh.Uri() + "'";
  if (!s->size.allFinite() || (s->size.array() == 0).any()) {
    std::ostringstream text;
    text << s->size.x() << " " << s->size.y() << " " << s->size.z();
    throw LoadError(where + ": <scale> '" + text.str() + "' must be finite and non-zero");
  }
  std::string reason;
  s->mesh = loadMeshUri(resolver_, mesh.Uri(), meshBaseDir(mesh, source_), &reason);
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
  if (!mesh.Submesh().empty()) {
    mesh_warnings_.push_back(where + ": <submesh> '" + mesh.Submesh() +
                             "' is not supported: the whole mesh is used");
  }
}

}  // namespace bullet_sim
