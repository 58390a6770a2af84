#include <algorithm>
#include <fstream>
#include <sstream>

#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/errors.h"
#include "description/robot_plan.h"
#include "description/sdf/sdf_model.h"
#include "description/sdf/sdf_reader.h"
#include "description/sdf/static_link_shapes.h"
#include "description/sdf/world_state.h"

namespace bullet_sim {
namespace {

using Eigen::Isometry3d;

/// The saved state of `name` among `states`, or null.
const ModelState* stateOf(const std::map<std::string, ModelState>& states,
                          const std::string& name) {
  const auto saved = states.find(name);
  return saved == states.end() ? nullptr : &saved->second;
}

/// Builds the shapes and movable models of one world and records where they came from.
class WorldReader {
 public:
  WorldReader(std::string source, const UriResolver& resolver)
      : source_(std::move(source)), resolver_(resolver), shapes_(source_, resolver) {}

  /// Reads the <state> first: its poses are checked with messages that name the value.
  /// With `documents`, the XML document and the model the world was read into go there
  /// instead of being freed before the spec is returned.
  WorldSpec read(const std::string& text, const std::string& path,
                 std::shared_ptr<const void>* documents = nullptr) {
    auto xml = parseSdfXml(text, source_, "world");
    const tinyxml2::XMLElement* sdf_element = xml->FirstChildElement("sdf");
    WorldSpec spec;
    const WorldState state = readWorldState(
        sdf_element ? sdf_element->FirstChildElement("world") : nullptr, source_, &spec.warnings);
    auto doc = std::make_unique<SdfDocument>(readSdf(*xml, source_, path, resolver_,
                                                     &spec.warnings));
    if (!doc->world) throw LoadError(source_ + ": no <world> element");
    const SdfWorld& world = *doc->world;
    spec.name = world.name;
    readSettings(world, &spec);
    for (const SdfModel& model : world.models) {
      readTopModel(model, stateOf(state.models, model.name), &spec);
    }
    for (const auto& saved : state.models) {
      const bool exists = std::any_of(world.models.begin(), world.models.end(),
                                      [&](const SdfModel& m) { return m.name == saved.first; });
      if (exists) continue;
      spec.warnings.push_back(source_ + ": <state> <model name=\"" + saved.first +
                              "\">: the world has no such model: its state is ignored");
    }
    const std::vector<std::string>& mesh_warnings = shapes_.meshWarnings();
    spec.warnings.insert(spec.warnings.end(), mesh_warnings.begin(), mesh_warnings.end());
    if (documents) {
      *documents = std::make_shared<Documents>(Documents{std::move(xml), std::move(doc)});
    }
    return spec;
  }

 private:
  struct Documents {
    std::unique_ptr<tinyxml2::XMLDocument> xml;
    std::unique_ptr<SdfDocument> world;
  };

  /// Gravity, step size, ambient light, the lights and the sun's direction.
  void readSettings(const SdfWorld& world, WorldSpec* spec) const {
    spec->gravity = world.gravity;
    spec->max_step_size_s = world.max_step_size_s;
    if (!(spec->max_step_size_s > 0)) {
      throw LoadError(source_ + ": <physics> <max_step_size>: must be > 0");
    }
    spec->ambient = world.ambient;
    bool sun_found = false;
    for (const SdfLight& light : world.lights) {
      LightSpec l;
      l.name = light.name;
      l.type = light.type;
      l.pose = toPose3(light.T_world_light);
      l.direction = (light.T_world_light.linear() * light.direction).normalized();
      l.diffuse = light.diffuse;
      l.specular = light.specular;
      l.range_m = light.range_m;
      l.constant = light.constant;
      l.linear = light.linear;
      l.quadratic = light.quadratic;
      l.spot_inner_rad = light.spot_inner_rad;
      l.spot_outer_rad = light.spot_outer_rad;
      l.spot_falloff = light.spot_falloff;
      l.cast_shadows = light.cast_shadows;
      if (l.type == "directional" && !sun_found) {
        spec->light_direction = l.direction;
        sun_found = true;
      }
      spec->lights.push_back(l);
    }
  }

  void readTopModel(const SdfModel& model, const ModelState* saved, WorldSpec* spec) {
    const Isometry3d T_world_model =
        saved && saved->pose ? toIsometry(*saved->pose) : model.T_parent_model;
    std::string anchor;
    bool anchor_fixed = true;
    const bool anchored = isAnchoredToWorld(model, &anchor, &anchor_fixed);
    if (anchored && !anchor_fixed) {
      spec->warnings.push_back(source_ + ": model '" + model.name + "': joint '" + anchor +
                               "' to the world is not fixed: the model is held static");
    }
    // A static model with sensors or plugins is a robot held static, so that they work.
    if ((model.is_static || anchored) && !carriesSensorsOrPlugins(model)) {
      readStaticModel(model, model.name, T_world_model, saved, spec);
      spec->static_models.push_back({model.name, toPose3(T_world_model)});
      return;
    }
    readMovableModel(model, T_world_model, saved, spec);
  }

  void readMovableModel(const SdfModel& model, const Isometry3d& T_world_model,
                        const ModelState* saved, WorldSpec* spec) const {
    WorldModel movable;
    movable.name = model.name;
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
  void readStaticModel(const SdfModel& model, const std::string& name,
                       const Isometry3d& T_world_model, const ModelState* saved,
                       WorldSpec* spec) {
    for (const SdfLink& link : model.links) {
      Isometry3d T_world_link = T_world_model * link.T_model_link;
      if (saved && saved->link_poses.count(link.name)) {
        T_world_link = toIsometry(saved->link_poses.at(link.name));
      }
      shapes_.read(name, link, T_world_link, spec);
    }
    for (const SdfModel& nested : model.models) {
      const ModelState* nested_saved = saved ? stateOf(saved->models, nested.name) : nullptr;
      const Isometry3d T_world_nested = nested_saved && nested_saved->pose
                                            ? toIsometry(*nested_saved->pose)
                                            : T_world_model * nested.T_parent_model;
      readStaticModel(nested, name + "::" + nested.name, T_world_nested, nested_saved, spec);
    }
  }

  std::string source_;
  const UriResolver& resolver_;
  StaticLinkShapes shapes_;
};

}  // namespace

WorldSpec loadWorldFile(const std::string& path) {
  return loadWorldFile(path, UriResolver(ResourcePaths::fromEnvironment()));
}

WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name) {
  return loadWorldString(sdf_xml, source_name, UriResolver(ResourcePaths::fromEnvironment()));
}

WorldSpec loadWorldFile(const std::string& path, const UriResolver& resolver) {
  return loadWorldFile(path, resolver, nullptr);
}

WorldSpec loadWorldFile(const std::string& path, const UriResolver& resolver,
                        std::shared_ptr<const void>* documents) {
  std::ifstream in(path);
  if (!in.good()) throw LoadError(path + ": world file does not exist or cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return WorldReader(path, resolver).read(text.str(), path, documents);
}

WorldSpec loadWorldString(const std::string& sdf_xml, const std::string& source_name,
                          const UriResolver& resolver) {
  return WorldReader(source_name, resolver).read(sdf_xml, "");
}

}  // namespace bullet_sim
