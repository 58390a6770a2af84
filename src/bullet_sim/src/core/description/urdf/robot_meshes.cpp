// Reads the mesh files a robot description names.
#include <cmath>
#include <sstream>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "description/description_geometry.h"

namespace bullet_sim {
namespace {

bool usableScale(const Eigen::Vector3d& scale) {
  return scale.allFinite() && (scale.array() != 0).all();
}

std::string scaleText(const Eigen::Vector3d& scale) {
  std::ostringstream out;
  out << scale.x() << " " << scale.y() << " " << scale.z();
  return out.str();
}

void loadCollisionMeshes(const UriResolver& resolver, const std::string& base_dir,
                         const std::string& source, const urdf::Link& link, RobotSpec* spec) {
  for (const urdf::CollisionSharedPtr& c : link.collision_array) {
    if (!c || !c->geometry) continue;
    const Geometry geometry = geometryOf(*c->geometry);
    if (geometry.kind != Geometry::Mesh) continue;
    const std::string& uri = geometry.mesh_uri;
    const std::string where = source + ": link '" + link.name + "' collision mesh '" + uri + "'";
    if (!usableScale(geometry.size)) {
      throw LoadError(where + ": scale '" + scaleText(geometry.size) +
                      "' must be finite and non-zero");
    }
    if (spec->collision_meshes.count(uri)) continue;
    std::string reason;
    auto mesh = loadMeshUri(resolver, uri, base_dir, &reason);
    if (!mesh) throw LoadError(where + ": " + reason);
    spec->collision_meshes[uri] = std::move(mesh);
  }
}

void loadVisualMesh(const UriResolver& resolver, const std::string& base_dir, VisualSpec* vis,
                    RobotSpec* spec) {
  const std::string where = "link '" + vis->link + "' visual mesh '" + vis->mesh_uri + "'";
  if (!usableScale(vis->size)) {
    spec->warnings.push_back(where + ": scale '" + scaleText(vis->size) +
                             "' must be finite and non-zero: not drawn");
    return;
  }
  std::string reason;
  vis->mesh = loadMeshUri(resolver, vis->mesh_uri, base_dir, &reason);
  if (!vis->mesh) spec->warnings.push_back(where + ": " + reason + ": not drawn");
}

}  // namespace

void loadRobotMeshes(const UriResolver& resolver, const std::string& base_dir,
                     const std::string& source, RobotSpec* spec) {
  std::vector<urdf::LinkSharedPtr> links;
  spec->urdf->getLinks(links);
  for (const urdf::LinkSharedPtr& link : links) {
    loadCollisionMeshes(resolver, base_dir, source, *link, spec);
  }
  for (VisualSpec& vis : spec->visuals) {
    if (vis.kind == VisualSpec::Mesh && !vis.mesh) loadVisualMesh(resolver, base_dir, &vis, spec);
  }
}

}  // namespace bullet_sim
