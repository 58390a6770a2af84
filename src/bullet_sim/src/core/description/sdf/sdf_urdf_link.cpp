#include "description/sdf/sdf_urdf_link.h"

#include <filesystem>
#include <memory>

#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/material/visual_appearance.h"
#include "description/sdf/sdf_surface.h"
#include "description/sdf/sdf_urdf_convert.h"
#include "description/sdf/sdf_util.h"
#include "description/urdf/urdf_checks.h"

namespace bullet_sim {
namespace {

urdf::InertialSharedPtr inertialOf(const sdf::Link& l) {
  const ignition::math::Inertiald& in = l.Inertial();
  auto inertial = std::make_shared<urdf::Inertial>();
  inertial->origin = toUrdfPose(sdfToIsometry(in.Pose()));
  inertial->mass = in.MassMatrix().Mass();
  inertial->ixx = in.MassMatrix().Ixx();
  inertial->iyy = in.MassMatrix().Iyy();
  inertial->izz = in.MassMatrix().Izz();
  inertial->ixy = in.MassMatrix().Ixy();
  inertial->ixz = in.MassMatrix().Ixz();
  inertial->iyz = in.MassMatrix().Iyz();
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
  const sdf::Link& l = *entry.link;
  auto out = std::make_shared<urdf::Link>();
  out->name = entry.name;
  out->inertial = inertialOf(l);
  const std::string where = where_ + " link '" + entry.name + "'";
  // libsdformat only warns about a bad inertia (static links may have one); a moving
  // link cannot be simulated with it.
  checkInertial(*out->inertial, where);
  addCollisions(l, entry.name, where, out.get());
  addVisuals(l, where, out.get());
  if (!out->collision_array.empty()) out->collision = out->collision_array.front();
  if (!out->visual_array.empty()) out->visual = out->visual_array.front();
  for (uint64_t i = 0; i < l.SensorCount(); ++i) {
    spec_->warnings.push_back(where + ": sensor '" + l.SensorByIndex(i)->Name() +
                              "' is not simulated (sensors of SDF models are not)");
  }
  return out;
}

void SdfLinkConverter::addCollisions(const sdf::Link& l, const std::string& link,
                                     const std::string& where, urdf::Link* out) {
  for (uint64_t i = 0; i < l.CollisionCount(); ++i) {
    const sdf::Collision& c = *l.CollisionByIndex(i);
    auto col = std::make_shared<urdf::Collision>();
    col->name = c.Name();
    col->origin = toUrdfPose(sdfToIsometry(poseInParent(c)));
    const std::string cwhere = where + " collision '" + c.Name() + "'";
    col->geometry = geometry(*c.Geom(), cwhere);
    out->collision_array.push_back(col);
    readFriction(c, link, cwhere);
  }
}

void SdfLinkConverter::addVisuals(const sdf::Link& l, const std::string& where,
                                  urdf::Link* out) {
  for (uint64_t i = 0; i < l.VisualCount(); ++i) {
    const sdf::Visual& v = *l.VisualByIndex(i);
    const std::string vwhere = where + " visual '" + v.Name() + "'";
    auto vis = std::make_shared<urdf::Visual>();
    vis->name = v.Name();
    vis->origin = toUrdfPose(sdfToIsometry(poseInParent(v)));
    vis->geometry = geometry(*v.Geom(), vwhere);
    const Appearance look = visualAppearance(v, vwhere, source_, resolver_, &spec_->warnings);
    if (!look.texture.path.empty()) textures_[vis.get()] = look.texture;
    vis->material = materialOf(look.rgba);
    out->visual_array.push_back(vis);
  }
}

urdf::GeometrySharedPtr SdfLinkConverter::geometry(const sdf::Geometry& g,
                                                   const std::string& where) const {
  checkGeometrySize(g, where);
  std::optional<Geometry> geometry = geometryOf(g);
  if (!geometry || geometry->kind == Geometry::Plane) {
    throw LoadError(where + ": geometry type '" + geometryName(g.Type()) +
                    "' is not supported for a movable model (box, cylinder, sphere, " +
                    "mesh are)");
  }
  if (geometry->kind == Geometry::Mesh) {
    const std::string base =
        std::filesystem::path(g.MeshShape()->FilePath()).parent_path().string();
    const std::string path = resolver_.resolve(geometry->mesh_uri, base);
    if (!path.empty()) geometry->mesh_uri = path;
  }
  return urdfGeometry(*geometry);
}

void SdfLinkConverter::readFriction(const sdf::Collision& c, const std::string& link,
                                    const std::string& where) {
  const auto known = spec_->surfaces.find(link);
  SurfaceParams s = known == spec_->surfaces.end() ? SurfaceParams() : known->second;
  if (readOdeFriction(c, where, &s)) spec_->surfaces[link] = s;
}

}  // namespace bullet_sim
