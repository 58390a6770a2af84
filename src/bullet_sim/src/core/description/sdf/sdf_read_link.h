#ifndef BULLET_SIM_CORE_SDF_READ_LINK_H
#define BULLET_SIM_CORE_SDF_READ_LINK_H

#include <string>
#include <vector>

#include <tinyxml2.h>

#include "description/sdf/sdf_dom.h"
#include "description/sdf/sdf_frames.h"
#include "description/sdf/sdf_values.h"

namespace bullet_sim {

/// A <link> of a model whose frames are in `scope` (the link itself among them): its
/// inertial, collisions, visuals and sensors, each posed in the link frame.
SdfLink readSdfLink(const tinyxml2::XMLElement* e, const SdfValues& values,
                    const FrameScope& scope, std::vector<std::string>* warnings);

/// The <geometry> child of a visual or collision, with the spec's defaults.
SdfGeometry readSdfGeometry(const tinyxml2::XMLElement* parent, const SdfValues& values);

/// A <plugin> element.
SdfPlugin readSdfPlugin(const tinyxml2::XMLElement* e, const SdfValues& values);

/// Every <plugin> child of `parent`, in order.
std::vector<SdfPlugin> readSdfPlugins(const tinyxml2::XMLElement* parent,
                                      const SdfValues& values);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_READ_LINK_H
