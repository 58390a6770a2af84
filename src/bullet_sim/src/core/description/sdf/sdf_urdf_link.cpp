#include "description/sdf/sdf_urdf_link.h"

#include <filesystem>
#include <memory>

#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/robot_plan.h"
#include "description/material/visual_appearance.h"
#include "description/sdf/sdf_surface.h"
#include "description/sdf/sdf_urdf_convert.h"
#include "description/sdf/sdf_util.h"
#include "description/urdf/urdf_checks.h"

namespace bullet_sim {
namespace {

urdf::InertialSharedPtr inertialOf(const SdfLink& l) {
  const SdfInertial& in = l.inertial;
  auto inertial = std::make_shared<urdf::Inertial>();
  inertial->origin = toUrdfPose(in.T_link_inertial);
  inertial->mass = in.mass;
  inertial->ixx = in.ixx;
  inertial->iyy = in.iyy;
  inertial->izz = in.izz;
  inertial->ixy = in.ixy;
  inertial->ixz = in.ixz;
  inertial->iyz = in.iyz;
  return inertial;
}

urdf::MaterialSharedPtr materialOf(const Eigen::Vector4f& rgba) {
  auto material = std::make_shared<urdf::Material>();
  material->color.r = rgba[0];
  material->color.g = rgba[1];
  material->color.b = rgba[2];
  material->color.a = rgba[3];
  return material;
}

}  // namespace

urdf::LinkSharedPtr SdfLinkConverter::convert(const LinkEntry& entry) {
  const SdfLink& l = *entry.link;
  auto out = std::make_shared<urdf::Link>();
  out->name = entry.name;
  const std::string where = where_ + " link '" + entry.name + "'";
  // Static links may have a bad inertia (Gazebo saves them with nan moments); a moving
  // link cannot be simulated with it. A static link's body never moves: any inertia does.
  if (is_static_) {
    out->inertial = std::make_shared<urdf::Inertial>();
    out->inertial->mass = out->inertial->ixx = out->inertial->iyy = out->inertial->izz = 1;
  } else {
    out->inertial = inertialOf(l);
    checkInertial(*out->inertial, where);
  }
  addCollisions(l, entry.name, where, out.get());
  addVisuals(l, where, out.get());
  if (!out->collision_array.empty()) out->collision = out->collision_array.front();
  if (!out->visual_array.empty()) out->visual = out->visual_array.front();
  for (const SdfSensor& sensor : l.sensors) {
    sensors_.push_back({sensor.xml, entry.name,
                        where + " <sensor name=\"" + sensor.name + "\">",
                        toPose3(sensor.T_link_sensor)});
  }
  return out;
}

void SdfLinkConverter::addCollisions(const SdfLink& l, const std::string& link,
                                     const std::string& where, urdf::Link* out) {
  for (const SdfCollision& c : l.collisions) {
    auto col = std::make_shared<urdf::Collision>();
    col->name = c.name;
    col->origin = toUrdfPose(c.T_link_collision);
    const std::string cwhere = where + " collision '" + c.name + "'";
    col->geometry = geometry(c.geometry, c.origin, cwhere);
    out->collision_array.push_back(col);
    readFriction(c, link, cwhere);
  }
}

void SdfLinkConverter::addVisuals(const SdfLink& l, const std::string& where,
                                  urdf::Link* out) {
  for (const SdfVisual& v : l.visuals) {
    const std::string vwhere = where + " visual '" + v.name + "'";
    auto vis = std::make_shared<urdf::Visual>();
    vis->name = v.name;
    vis->origin = toUrdfPose(v.T_link_visual);
    vis->geometry = geometry(v.geometry, v.origin, vwhere);
    const Appearance look = visualAppearance(v, vwhere, resolver_, &spec_->warnings);
    if (!look.texture.path.empty()) textures_[vis.get()] = look.texture;
    vis->material = materialOf(look.rgba);
    out->visual_array.push_back(vis);
  }
}

urdf::GeometrySharedPtr SdfLinkConverter::geometry(const SdfGeometry& g,
                                                   const SdfOrigin& origin,
                                                   const std::string& where) const {
  checkGeometrySize(g, where);
  std::optional<Geometry> geometry = g.shape;
  if (!geometry || geometry->kind == Geometry::Plane) {
    throw LoadError(where + ": geometry type '" + g.type +
                    "' is not supported for a movable model (box, cylinder, sphere, " +
                    "mesh are)");
  }
  if (geometry->kind == Geometry::Mesh) {
    std::error_code ec;
    const std::string base = std::filesystem::is_regular_file(origin.file, ec)
                                 ? std::filesystem::path(origin.file).parent_path().string()
                                 : "";
    const std::string path = resolver_.resolve(geometry->mesh_uri, base);
    if (!path.empty()) geometry->mesh_uri = path;
  }
  return urdfGeometry(*geometry);
}

void SdfLinkConverter::readFriction(const SdfCollision& c, const std::string& link,
                                    const std::string& where) {
  const auto known = spec_->surfaces.find(link);
  SurfaceParams s = known == spec_->surfaces.end() ? SurfaceParams() : known->second;
  if (readOdeFriction(c, where, &s)) spec_->surfaces[link] = s;
}

}  // namespace bullet_sim
