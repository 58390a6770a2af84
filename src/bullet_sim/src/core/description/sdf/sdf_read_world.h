#ifndef BULLET_SIM_CORE_SDF_READ_WORLD_H
#define BULLET_SIM_CORE_SDF_READ_WORLD_H

#include <tinyxml2.h>

#include "description/sdf/sdf_dom.h"
#include "description/sdf/sdf_frames.h"
#include "description/sdf/sdf_read_context.h"

namespace bullet_sim {

/// A <world>: physics, scene, lights, models (included ones too), frames and plugins.
SdfWorld readSdfWorld(const tinyxml2::XMLElement* e, const SdfValues& values,
                      SdfReadContext* context);

/// A <light>, posed in the world frame through `world_frames` (null: its pose as written).
SdfLight readSdfLight(const tinyxml2::XMLElement* e, const SdfValues& values,
                      const FrameScope* world_frames);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_READ_WORLD_H
