#include <filesystem>
#include <fstream>
#include <sstream>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/material/visual_appearance.h"
#include "description/robot_plan.h"
#include "description/sdf/sdf_document.h"
#include "description/sdf/sdf_model.h"
#include "description/sdf/sdf_surface.h"
#include "description/sdf/sdf_util.h"
#include "description/sdf/world_state.h"

namespace bullet_sim {
namespace {

using Eigen::Isometry3d;

Isometry3d toIso(const ignition::math::Pose3d& p) { return toIsometry(toPose(p)); }

/// Builds the shapes and movable models of one world and records where they came from.
class WorldReader {
 public:
  WorldReader(std::string source, const UriResolver& resolver)
      : source_(std::move(source)), resolver_(resolver) {}

  /// Reads the <state> first: its poses are checked with messages that name the value.
  WorldSpec read(const std::string& text, const std::string& path) {
    const auto xml = parseSdfXml(text, source_, "world");
    const tinyxml2::XMLElement* sdf_element = xml->FirstChildElement("sdf");
    WorldSpec spec;
    const WorldState state = readWorldState(
        sdf_element ? sdf_element->FirstChildElement("world") : nullptr, source_, &spec.warnings);
    const auto root = loadSdfRoot(text, source_, path, resolver_, "world", &spec.warnings);
    if (root->WorldCount() == 0) throw LoadError(source_ + ": no <world> element");
    const sdf::World& world = *root->WorldByIndex(0);
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
    readLight(world, &spec);
    for (uint64_t i = 0; i < world.ModelCount(); ++i) {
      const sdf::Model& model = *world.ModelByIndex(i);
      const auto saved = state.models.find(model.Name());
      readTopModel(model, saved == state.models.end() ? nullptr : &saved->second, &spec);
    }
    for (const auto& saved : state.models) {
      if (world.ModelNameExists(saved.first)) continue;
      spec.warnings.push_back(source_ + ": <state> <model name=\"" + saved.first +
                              "\">: the world has no such model: its state is ignored");
    }
    spec.warnings.insert(spec.warnings.end(), mesh_warnings_.begin(), mesh_warnings_.end());
    return spec;
  }

 private:
  void readLight(const sdf::World& world, WorldSpec* spec) const {
    for (uint64_t i = 0; i < world.LightCount(); ++i) {
      const sdf::Light& light = *world.LightByIndex(i);
      if (light.Type() == sdf::LightType::DIRECTIONAL) {
        const auto d = toPose(poseInParent(light)).orientation *
                       Eigen::Vector3d(light.Direction().X(), light.Direction().Y(),
                                       light.Direction().Z());
        spec->light_direction = d.normalized();
        return;
      }
    }
  }

  void readTopModel(const sdf::Model& model, const ModelState* saved, WorldSpec* spec) {
    const Isometry3d T_world_model =
        saved && saved->pose ? toIsometry(*saved->pose) : toIso(poseInParent(model));
    std::string anchor;
    bool anchor_fixed = true;
    const bool anchored = isAnchoredToWorld(model, &anchor, &anchor_fixed);
    if (anchored && !anchor_fixed) {
      spec->warnings.push_back(source_ + ": model '" + model.Name() + "': joint '" + anchor +
                               "' to the world is not fixed: the model is held static");
    }
    if (model.Static() || anchored) {
      readStaticModel(model, model.Name(), T_world_model, saved, spec);
      spec->static_models.push_back({model.Name(), toPose3(T_world_model)});
      return;
    }
    WorldModel movable;
    movable.name = model.Name();
    movable.spec = parseSdfModel(model, source_, resolver_);
    movable.pose = toPose3(T_world_model);
    // A saved pose of the root link places the model (its joints are not set from <state>).
    if (saved) {
      const std::string& root = movable.spec.urdf->getRoot()->name;
      const auto link = saved->link_poses.find(root);
      if (link != saved->link_poses.end()) {
        movable.pose = toPose3(toIsometry(link->second) *
                               toIsometry(movable.spec.root_link_in_model).inverse());
      }
    }
    spec->warnings.insert(spec->warnings.end(), movable.spec.warnings.begin(),
                          movable.spec.warnings.end());
    spec->models.push_back(std::move(movable));
  }

  /// A static model and its nested models, with the link poses of a saved state.
  void readStaticModel(const sdf::Model& model, const std::string& name,
                       const Isometry3d& T_world_model, const ModelState* saved,
                       WorldSpec* spec) {
    for (uint64_t l = 0; l < model.LinkCount(); ++l) {
      const sdf::Link& link = *model.LinkByIndex(l);
      Isometry3d T_world_link = T_world_model * toIso(poseInParent(link));
      if (saved && saved->link_poses.count(link.Name())) {
        T_world_link = toIsometry(saved->link_poses.at(link.Name()));
      }
      readLink(name, link, T_world_link, spec);
    }
    for (uint64_t m = 0; m < model.ModelCount(); ++m) {
      const sdf::Model& nested = *model.ModelByIndex(m);
      const ModelState* nested_saved = nullptr;
      if (saved && saved->models.count(nested.Name())) nested_saved = &saved->models.at(nested.Name());
      const Isometry3d T_world_nested = nested_saved && nested_saved->pose
                                            ? toIsometry(*nested_saved->pose)
                                            : T_world_model * toIso(poseInParent(nested));
      readStaticModel(nested, name + "::" + nested.Name(), T_world_nested, nested_saved, spec);
    }
  }

  void readLink(const std::string& model, const sdf::Link& link, const Isometry3d& T_world_link,
                WorldSpec* spec) {
    for (uint64_t c = 0; c < link.CollisionCount(); ++c) {
      const sdf::Collision& col = *link.CollisionByIndex(c);
      const std::string where = source_ + ": model '" + model + "' link '" + link.Name() +
                                "' collision '" + col.Name() + "'";
      checkGeometrySize(*col.Geom(), where);
      StaticShape s = shape(model, link, *col.Geom(), T_world_link * toIso(poseInParent(col)), true);
      if (s.kind == Geometry::Mesh && !s.mesh) continue;  // not found: warned, left out
      SurfaceParams surface;
      readOdeFriction(col, where, &surface);
      s.friction = surface.isotropicMu();
      spec->shapes.push_back(std::move(s));
    }
    for (uint64_t v = 0; v < link.VisualCount(); ++v) {
      const sdf::Visual& vis = *link.VisualByIndex(v);
      checkGeometrySize(*vis.Geom(), source_ + ": model '" + model + "' link '" + link.Name() +
                                         "' visual '" + vis.Name() + "'");
      StaticShape s = shape(model, link, *vis.Geom(), T_world_link * toIso(poseInParent(vis)), false);
      const Appearance look = visualAppearance(
          vis, source_ + ": model '" + model + "' link '" + link.Name() + "' visual '" +
                   vis.Name() + "'",
          source_, resolver_, &spec->warnings);
      s.rgba = look.rgba;
      s.texture = look.texture;
      mergeVisual(s, spec);
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
        s.texture = visual.texture;
        return;
      }
    }
    spec->shapes.push_back(visual);
  }

  StaticShape shape(const std::string& model, const sdf::Link& link, const sdf::Geometry& geom,
                    const Isometry3d& pose, bool collides) const {
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

  /// A mesh's triangles: its file resolved from the folder of the SDF file that names it.
  /// A collision mesh that cannot be read is an error, a visual one a warning (not drawn).
  void meshShape(const std::string& model, const sdf::Link& link, const sdf::Mesh& mesh,
                 bool collides, StaticShape* s) const {
    const std::string where = source_ + ": model '" + model + "' link '" + link.Name() +
                              "' " + (collides ? "collision" : "visual") + " mesh '" +
                              mesh.Uri() + "'";
    if (!s->size.allFinite() || (s->size.array() == 0).any()) {
      std::ostringstream text;
      text << s->size.x() << " " << s->size.y() << " " << s->size.z();
      throw LoadError(where + ": <scale> '" + text.str() + "' must be finite and non-zero");
    }
    const std::string defined_in = mesh.FilePath().empty() ? source_ : mesh.FilePath();
    std::error_code ec;
    const std::string base_dir = std::filesystem::is_regular_file(defined_in, ec)
                                     ? std::filesystem::path(defined_in).parent_path().string()
                                     : "";
    std::string reason;
    s->mesh = loadMeshUri(resolver_, mesh.Uri(), base_dir, &reason);
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

  std::string source_;
  const UriResolver& resolver_;
  mutable std::vector<std::string> mesh_warnings_;  ///< moved into the spec by read()
};

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
  return WorldReader(path, resolver).read(text.str(), path);
}

WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name,
                          const UriResolver& resolver) {
  return WorldReader(source_name, resolver).read(sdf_xml, "");
}

}  // namespace bullet_sim
