#ifndef BULLET_SIM_CORE_SCENE_LIGHTS_H
#define BULLET_SIM_CORE_SCENE_LIGHTS_H

#include <sim_render/scene.h>

#include "bullet_sim/description/world_spec.h"

namespace bullet_sim {

/// Lights the renderer's scene with the world's lights, as Gazebo's rendering::Light hands
/// them to OGRE: the sun (the first directional light) as `lighting->direction` with the
/// renderer's sun colour, the ambient colour, and every other light in `lighting->lights`
/// (point and spot lights with their attenuation and cone, further directional lights).
/// Gazebo clamps the constant and linear attenuation factors to [0, 1] before OGRE sees
/// them; so does this. Cheap (a few lights): called for every frame, so that lights changed
/// while the simulation runs are drawn as they are now.
void lightScene(const WorldSpec& world, sim_render::Lighting* lighting);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SCENE_LIGHTS_H
