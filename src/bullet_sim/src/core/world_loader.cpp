#include <filesystem>
#include <fstream>
#include <sstream>

#include <sdf/sdf.hh>
#include <tinyxml2.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/mesh.h"
#include "bullet_sim/world_spec.h"

namespace bullet_sim {
namespace {

using ignition::math::Pose3d;

Pose3 toPose(const Pose3d& p) {
  Pose3 out;
  out.position = Eigen::Vector3d(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  out.orientation = Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z());
  return out;
}

/// Pose of an element in its parent's frame (relative_to honoured when it resolves).
template <typename T>
Pose3d poseInParent(const T& element) {
  Pose3d pose;
  if (!element.SemanticPose().Resolve(pose).empty()) pose = element.RawPose();
  return pose;
}

std::string geometryName(sdf::GeometryType type) {
  switch (type) {
    case sdf::GeometryType::EMPTY: return "empty";
    case sdf::GeometryType::BOX: return "box";
    case sdf::GeometryType::CYLINDER: return "cylinder";
    case sdf::GeometryType::PLANE: return "plane";
    case sdf::GeometryType::SPHERE: return "sphere";
    case sdf::GeometryType::MESH: return "mesh";
    case sdf::GeometryType::HEIGHTMAP: return "heightmap";
    case sdf::GeometryType::CAPSULE: return "capsule";
    case sdf::GeometryType::ELLIPSOID: return "ellipsoid";
    default: return "polyline";
  }
}

/// Builds the StaticShapes of one world and records where they came from.
class WorldReader {
 public:
  WorldReader(std::string source, const UriResolver& resolver)
      : source_(std::move(source)), resolver_(resolver) {}

  WorldSpec read(const sdf::Root& root) {
    if (root.WorldCount() == 0) throw LoadError(source_ + ": no <world> element");
    const sdf::World& world = *root.WorldByIndex(0);
    WorldSpec spec;
    spec.name = world.Name();
    const auto g = world.Gravity();
    spec.gravity = Eigen::Vector3d(g.X(), g.Y(), g.Z());
    if (world.PhysicsCount() > 0) {
      spec.max_step_size_s = world.PhysicsByIndex(0)->MaxStepSize();
      if (!(spec.max_step_size_s > 0)) {
        throw LoadError(source_ + ": <physics> <max_step_size>: must be > 0");
      }
    }
    if (const sdf::Scene* scene = world.Scene()) {
      const auto a = scene->Ambient();
      spec.ambient = Eigen::Vector4f(a.R(), a.G(), a.B(), a.A());
    }
    for (uint64_t i = 0; i < world.LightCount(); ++i) {
      const sdf::Light& light = *world.LightByIndex(i);
      if (light.Type() == sdf::LightType::DIRECTIONAL) {
        const auto d = toPose(poseInParent(light)).orientation *
                       Eigen::Vector3d(light.Direction().X(), light.Direction().Y(),
                                       light.Direction().Z());
        spec.light_direction = d.normalized();
        break;
      }
    }
    for (uint64_t i = 0; i < world.ModelCount(); ++i) {
      readModel(*world.ModelByIndex(i), Pose3d::Zero, &spec);
    }
    spec.warnings.insert(spec.warnings.end(), mesh_warnings_.begin(), mesh_warnings_.end());
    return spec;
  }

 private:
  void readModel(const sdf::Model& model, const Pose3d& parent_in_world, WorldSpec* spec) {
    const Pose3d model_in_world = poseInParent(model) + parent_in_world;
    if (!model.Static()) {
      spec->warnings.push_back(source_ + ": model '" + model.Name() +
                               "' is not static: it is simulated as a static model");
    }
    for (uint64_t l = 0; l < model.LinkCount(); ++l) {
      const sdf::Link& link = *model.LinkByIndex(l);
      const Pose3d link_in_world = poseInParent(link) + model_in_world;
      for (uint64_t c = 0; c < link.CollisionCount(); ++c) {
        const sdf::Collision& col = *link.CollisionByIndex(c);
        spec->shapes.push_back(
            shape(model, link, *col.Geom(), poseInParent(col) + link_in_world, true));
      }
      for (uint64_t v = 0; v < link.VisualCount(); ++v) {
        const sdf::Visual& vis = *link.VisualByIndex(v);
        StaticShape s = shape(model, link, *vis.Geom(), poseInParent(vis) + link_in_world, false);
        if (vis.Material()) {
          const auto c = vis.Material()->Diffuse();
          s.rgba = Eigen::Vector4f(c.R(), c.G(), c.B(), c.A());
        }
        mergeVisual(s, spec);
      }
    }
    for (uint64_t m = 0; m < model.ModelCount(); ++m) {
      readModel(*model.ModelByIndex(m), model_in_world, spec);
    }
  }

  /// A visual equal to a collision shape of the same link colours it instead
  /// of adding a second, visual-only shape.
  static void mergeVisual(const StaticShape& visual, WorldSpec* spec) {
    for (StaticShape& s : spec->shapes) {
      if (s.collides && s.model == visual.model && s.link == visual.link &&
          s.kind == visual.kind && s.mesh == visual.mesh && s.size.isApprox(visual.size, 1e-9) &&
          (s.pose.position - visual.pose.position).norm() < 1e-9 &&
          s.pose.orientation.angularDistance(visual.pose.orientation) < 1e-9) {
        s.rgba = visual.rgba;
        return;
      }
    }
    spec->shapes.push_back(visual);
  }

  StaticShape shape(const sdf::Model& model, const sdf::Link& link, const sdf::Geometry& geom,
                    const Pose3d& pose, bool collides) const {
    StaticShape s;
    s.model = model.Name();
    s.link = link.Name();
    s.pose = toPose(pose);
    s.collides = collides;
    switch (geom.Type()) {
      case sdf::GeometryType::BOX: {
        const auto size = geom.BoxShape()->Size();
        s.kind = StaticShape::Box;
        s.size = Eigen::Vector3d(size.X(), size.Y(), size.Z());
        break;
      }
      case sdf::GeometryType::CYLINDER:
        s.kind = StaticShape::Cylinder;
        s.size = Eigen::Vector3d(geom.CylinderShape()->Radius(), geom.CylinderShape()->Radius(),
                                 geom.CylinderShape()->Length());
        break;
      case sdf::GeometryType::SPHERE:
        s.kind = StaticShape::Sphere;
        s.size = Eigen::Vector3d::Constant(geom.SphereShape()->Radius());
        break;
      case sdf::GeometryType::PLANE: {
        const auto n = geom.PlaneShape()->Normal();
        s.kind = StaticShape::Plane;
        s.size = Eigen::Vector3d(geom.PlaneShape()->Size().X(), geom.PlaneShape()->Size().Y(), 0);
        s.normal = Eigen::Vector3d(n.X(), n.Y(), n.Z()).normalized();
        break;
      }
      case sdf::GeometryType::MESH:
        meshShape(model, link, *geom.MeshShape(), collides, &s);
        break;
      default:
        throw LoadError(source_ + ": model '" + model.Name() + "' link '" + link.Name() + "' " +
                        (collides ? "collision" : "visual") + ": geometry type '" +
                        geometryName(geom.Type()) +
                        "' is not supported (box, cylinder, sphere, plane, mesh are)");
    }
    return s;
  }

  /// A mesh: its file resolved from the folder of the SDF file that names it. A collision
  /// mesh that cannot be read is an error, a visual one a warning (not drawn).
  void meshShape(const sdf::Model& model, const sdf::Link& link, const sdf::Mesh& mesh,
                 bool collides, StaticShape* s) const {
    const std::string where = source_ + ": model '" + model.Name() + "' link '" + link.Name() +
                              "' " + (collides ? "collision" : "visual") + " mesh '" +
                              mesh.Uri() + "'";
    const auto scale = mesh.Scale();
    s->kind = StaticShape::Mesh;
    s->size = Eigen::Vector3d(scale.X(), scale.Y(), scale.Z());
    if (!s->size.allFinite() || (s->size.array() == 0).any()) {
      std::ostringstream text;
      text << scale.X() << " " << scale.Y() << " " << scale.Z();
      throw LoadError(where + ": <scale> '" + text.str() + "' must be finite and non-zero");
    }
    const std::string defined_in = mesh.FilePath().empty() ? source_ : mesh.FilePath();
    std::error_code ec;
    const std::string base_dir = std::filesystem::is_regular_file(defined_in, ec)
                                     ? std::filesystem::path(defined_in).parent_path().string()
                                     : "";
    std::string reason;
    s->mesh = loadMeshUri(resolver_, mesh.Uri(), base_dir, &reason);
    if (!s->mesh && collides) throw LoadError(where + ": " + reason);
    if (!s->mesh) mesh_warnings_.push_back(where + ": " + reason + ": not drawn");
    if (!mesh.Submesh().empty()) {
      mesh_warnings_.push_back(where + ": <submesh> '" + mesh.Submesh() +
                               "' is not supported: the whole mesh is used");
    }
  }

  std::string source_;
  const UriResolver& resolver_;
  mutable std::vector<std::string> mesh_warnings_;  ///< moved into the spec by read()
};

std::string describe(const sdf::Errors& errors) {
  std::ostringstream out;
  for (size_t i = 0; i < errors.size(); ++i) out << (i ? "; " : "") << errors[i].Message();
  return out.str();
}

/// sdformat reports malformed XML only as "Unable to read file"; tinyxml2
/// (the parser it uses) says what and where.
void checkXml(const std::string& xml, const std::string& source) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw LoadError(source + ": invalid SDF world: malformed XML: " + doc.ErrorStr());
  }
}

}  // namespace

WorldSpec loadWorldFile(const std::string& path) {
  return loadWorldFile(path, UriResolver(ResourcePaths::fromEnvironment()));
}

WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name) {
  return loadWorldString(sdf_xml, source_name, UriResolver(ResourcePaths::fromEnvironment()));
}

WorldSpec loadWorldFile(const std::string& path, const UriResolver& resolver) {
  std::ifstream in(path);
  if (!in.good()) throw LoadError(path + ": world file does not exist or cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  checkXml(text.str(), path);
  sdf::Root root;
  const sdf::Errors errors = root.Load(path);
  if (!errors.empty()) throw LoadError(path + ": invalid SDF world: " + describe(errors));
  return WorldReader(path, resolver).read(root);
}

WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name,
                          const UriResolver& resolver) {
  checkXml(sdf_xml, source_name);
  sdf::Root root;
  const sdf::Errors errors = root.LoadSdfString(sdf_xml);
  if (!errors.empty()) throw LoadError(source_name + ": invalid SDF world: " + describe(errors));
  return WorldReader(source_name, resolver).read(root);
}

}  // namespace bullet_sim
