#include "description/sdf/sdf_read_world.h"

#include "description/sdf/sdf_read_link.h"
#include "description/sdf/sdf_read_model.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// The <physics> Gazebo uses: the one marked default="true", else the first.
const XMLElement* physicsOf(const XMLElement* world) {
  for (const XMLElement* p = world->FirstChildElement("physics"); p;
       p = p->NextSiblingElement("physics")) {
    const std::string is_default = SdfValues::attribute(p, "default");
    if (is_default == "true" || is_default == "1") return p;
  }
  return world->FirstChildElement("physics");
}

class WorldReader {
 public:
  WorldReader(const XMLElement* e, const SdfValues& values, SdfReadContext* context)
      : e_(e), v_(values), context_(context) {}

  SdfWorld read() {
    SdfWorld w;
    w.name = v_.requiredAttribute(e_, "name");
    w.origin = v_.origin(e_);
    const XMLElement* physics = physicsOf(e_);
    // SDF 1.6 moved <gravity> from <physics> to <world>.
    w.gravity = v_.vector3(v_.version().before(1, 6) ? physics : e_, "gravity", w.gravity);
    if (physics) {
      w.max_step_size_s = v_.number(physics, "max_step_size", w.max_step_size_s);
      w.real_time_update_rate_hz =
          v_.number(physics, "real_time_update_rate", w.real_time_update_rate_hz);
      w.real_time_factor = v_.number(physics, "real_time_factor", w.real_time_factor);
    }
    if (const XMLElement* scene = e_->FirstChildElement("scene")) {
      w.ambient = v_.color(scene, "ambient", w.ambient);
      w.background = v_.color(scene, "background", w.background);
    }
    frames_ = std::make_unique<FrameScope>("world", "world '" + w.name + "'");
    for (const XMLElement* c = e_->FirstChildElement(); c; c = c->NextSiblingElement()) {
      readChild(c, &w);
    }
    for (size_t i = 0; i < w.models.size(); ++i) {
      w.models[i].T_parent_model = frames_->resolve(w.models[i].name, model_elements_[i], v_);
    }
    for (size_t i = 0; i < w.lights.size(); ++i) {
      w.lights[i].T_world_light =
          frames_->resolvePose(light_poses_[i], "world", light_elements_[i], v_);
    }
    w.plugins = readSdfPlugins(e_, v_);
    return w;
  }

 private:
  void readChild(const XMLElement* c, SdfWorld* w) {
    const std::string tag = c->Name();
    if (tag == "model") {
      addModel(readSdfModel(c, v_, true, {}, context_), c, w);
    } else if (tag == "light") {
      addLight(readSdfLight(c, v_, nullptr), v_.pose(c), c, w);
    } else if (tag == "frame") {
      const std::string attached = SdfValues::attribute(c, "attached_to");
      frames_->add(v_.requiredAttribute(c, "name"), v_.pose(c),
                   attached.empty() ? "world" : attached, c, v_);
    } else if (tag == "include") {
      addIncluded(c, w);
    }
  }

  void addModel(ReadModel model, const XMLElement* element, SdfWorld* w) {
    frames_->add(model.model.name, model.pose, "world", element, v_);
    frames_->addNested(model.model.name, std::move(model.frames));
    w->models.push_back(std::move(model.model));
    model_elements_.push_back(element);
  }

  void addLight(SdfLight light, const RawPose& pose, const XMLElement* element, SdfWorld* w) {
    w->lights.push_back(std::move(light));
    light_poses_.push_back(pose);
    light_elements_.push_back(element);
  }

  /// An included model or light (model://sun is a light): the include's <name> and <pose>
  /// replace the included file's; a pose written there is relative to frames of that file.
  void addIncluded(const XMLElement* include, SdfWorld* w) {
    const IncludeOverrides overrides = readIncludeOverrides(include, v_);
    const SdfReadContext::Included inc = context_->include(include, v_);
    const std::string root = inc.root->Name();
    if (root == "model") {
      ReadModel model = readSdfModel(inc.root, *inc.values, true, overrides, context_);
      if (!overrides.pose) model.pose.relative_to.clear();
      context_->leave();
      addModel(std::move(model), include, w);
      return;
    }
    if (root == "light") {
      SdfLight light = readSdfLight(inc.root, *inc.values, nullptr);
      if (overrides.name) light.name = *overrides.name;
      RawPose pose = overrides.pose ? *overrides.pose : RawPose{light.T_world_light, ""};
      context_->leave();
      addLight(std::move(light), pose, include, w);
      return;
    }
    context_->warnings()->push_back(v_.where(include) + ": includes a <" + root +
                                    ">, which the simulator does not load: left out");
    context_->leave();
  }

  const XMLElement* e_;
  const SdfValues& v_;
  SdfReadContext* context_;
  std::unique_ptr<FrameScope> frames_;
  std::vector<const XMLElement*> model_elements_, light_elements_;
  std::vector<RawPose> light_poses_;
};

}  // namespace

SdfWorld readSdfWorld(const XMLElement* e, const SdfValues& values, SdfReadContext* context) {
  return WorldReader(e, values, context).read();
}

SdfLight readSdfLight(const XMLElement* e, const SdfValues& values,
                      const FrameScope* world_frames) {
  SdfLight l;
  l.name = values.requiredAttribute(e, "name");
  l.type = SdfValues::attribute(e, "type", "point");
  if (l.type != "point" && l.type != "directional" && l.type != "spot") {
    values.fail(e, "type '" + l.type + "' is not a light type (point, directional, spot)");
  }
  l.origin = values.origin(e);
  l.T_world_light = world_frames ? world_frames->resolvePose(values.pose(e), "world", e, values)
                                 : values.pose(e).T;
  l.diffuse = values.color(e, "diffuse", l.diffuse);
  l.specular = values.color(e, "specular", l.specular);
  if (const XMLElement* a = e->FirstChildElement("attenuation")) {
    l.range_m = values.number(a, "range", l.range_m);
    l.constant = values.number(a, "constant", l.constant);
    l.linear = values.number(a, "linear", l.linear);
    l.quadratic = values.number(a, "quadratic", l.quadratic);
  }
  l.direction = values.vector3(e, "direction", l.direction);
  if (const XMLElement* spot = e->FirstChildElement("spot")) {
    l.spot_inner_rad = values.number(spot, "inner_angle", 0);
    l.spot_outer_rad = values.number(spot, "outer_angle", 0);
    l.spot_falloff = values.number(spot, "falloff", 0);
  }
  l.cast_shadows = values.boolean(e, "cast_shadows", false);
  return l;
}

}  // namespace bullet_sim
