// Worlds and lights as libsdformat reads them.
#include "oracle_parts.h"

namespace bullet_sim_test {
namespace oracle {

namespace {

std::string lightTypeName(const sdf::Light& light) {
  switch (light.Type()) {
    case sdf::LightType::POINT: return "point";
    case sdf::LightType::DIRECTIONAL: return "directional";
    case sdf::LightType::SPOT: return "spot";
    default: return light.Element() ? light.Element()->Get<std::string>("type") : "";
  }
}

/// <physics> of the world: the one libsdformat takes as the default profile.
void readPhysics(const sdf::World& world, bullet_sim::SdfWorld* out) {
  const sdf::Physics* physics = world.PhysicsDefault();
  if (!physics) return;
  out->max_step_size_s = physics->MaxStepSize();
  out->real_time_factor = physics->RealTimeFactor();
  // sdf::Physics has no accessor for the update rate: its element tree has it.
  if (physics->Element()) {
    out->real_time_update_rate_hz = physics->Element()->Get<double>("real_time_update_rate");
  }
}

}  // namespace

bullet_sim::SdfLight lightOf(const sdf::Light& light, bool in_world, Problems* problems) {
  bullet_sim::SdfLight out;
  out.name = light.Name();
  out.type = lightTypeName(light);
  out.origin = originOf(light.Element());
  // A light that is a document of its own (model://sun's file) has no frame graph to
  // resolve in: its pose is the one written.
  out.T_world_light = in_world ? resolvedPose(light.SemanticPose(), "", "light '" + out.name + "'",
                                              problems)
                               : toIsometry(light.RawPose());
  out.diffuse = toColour(light.Diffuse());
  out.specular = toColour(light.Specular());
  out.range_m = light.AttenuationRange();
  out.constant = light.ConstantAttenuationFactor();
  out.linear = light.LinearAttenuationFactor();
  out.quadratic = light.QuadraticAttenuationFactor();
  out.direction = toVector(light.Direction());
  out.spot_inner_rad = light.SpotInnerAngle().Radian();
  out.spot_outer_rad = light.SpotOuterAngle().Radian();
  out.spot_falloff = light.SpotFalloff();
  out.cast_shadows = light.CastShadows();
  return out;
}

bullet_sim::SdfWorld worldOf(const sdf::World& world, OracleResult* result) {
  bullet_sim::SdfWorld out;
  out.name = world.Name();
  out.origin = originOf(world.Element());
  out.gravity = toVector(world.Gravity());
  readPhysics(world, &out);
  if (const sdf::Scene* scene = world.Scene()) {
    out.ambient = toColour(scene->Ambient());
    out.background = toColour(scene->Background());
  }
  for (uint64_t i = 0; i < world.LightCount(); ++i) {
    out.lights.push_back(lightOf(*world.LightByIndex(i), true, &result->errors));
  }
  for (uint64_t i = 0; i < world.ModelCount(); ++i) {
    const sdf::Model& model = *world.ModelByIndex(i);
    out.models.push_back(modelOf(model, modelFieldPath("world", model.Name()), result));
  }
  out.plugins = pluginsOf(world.Element());
  return out;
}

}  // namespace oracle
}  // namespace bullet_sim_test
