#include "render/scene_lights.h"

#include <algorithm>

namespace bullet_sim {
namespace {

sim_render::LocalLight localLight(const LightSpec& light) {
  sim_render::LocalLight l;
  if (light.type == "spot") {
    l.kind = sim_render::LocalLight::Kind::Spot;
  } else if (light.type == "directional") {
    l.kind = sim_render::LocalLight::Kind::Directional;
  } else {
    l.kind = sim_render::LocalLight::Kind::Point;
  }
  l.position = light.pose.position;
  l.direction = light.direction;
  l.diffuse = light.diffuse.head<3>();
  l.range_m = light.range_m;
  // rendering::Light::SetAttenuation: constant and linear each clamped to [0, 1].
  l.constant = std::clamp(light.constant, 0.0, 1.0);
  l.linear = std::clamp(light.linear, 0.0, 1.0);
  l.quadratic = light.quadratic;
  // SDF's angles go to Ogre::Light::setSpotlightRange unchanged: full cone angles.
  l.spot_inner_rad = light.spot_inner_rad;
  l.spot_outer_rad = light.spot_outer_rad;
  l.spot_falloff = light.spot_falloff;
  return l;
}

}  // namespace

void lightScene(const WorldSpec& world, sim_render::Lighting* lighting) {
  lighting->ambient = world.ambient.head<3>();
  lighting->direction = world.light_direction;
  lighting->lights.clear();
  bool sun_seen = false;
  for (const LightSpec& light : world.lights) {
    if (light.type == "directional" && !sun_seen) {
      lighting->direction = light.direction;
      sun_seen = true;
      continue;
    }
    lighting->lights.push_back(localLight(light));
  }
}

}  // namespace bullet_sim
