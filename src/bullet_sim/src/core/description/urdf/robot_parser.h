#ifndef BULLET_SIM_CORE_ROBOT_PARSER_H
#define BULLET_SIM_CORE_ROBOT_PARSER_H

#include <urdf_model/link.h>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// Appends one VisualSpec per <visual> of `link` (with its material colour) to spec->visuals:
/// the camera draws robots from these, whether they came from URDF or SDF.
void addLinkVisuals(const urdf::Link& link, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_ROBOT_PARSER_H
