#ifndef BULLET_SIM_CORE_SDF_MODEL_H
#define BULLET_SIM_CORE_SDF_MODEL_H

#include <string>

#include "bullet_sim/description/robot_spec.h"
#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// Converts a read SDF model into a RobotSpec (see parseSdfModelString). `source` names
/// the file in messages. Joints to the world are left out (see isAnchoredToWorld). A
/// <static> model, or one anchored to the world, gives a static spec (RobotSpec::is_static):
/// every link fixed where the model puts it.
/// @throws LoadError for geometry a movable body cannot have, or a model without links.
RobotSpec parseSdfModel(const SdfModel& model, const std::string& source,
                        const UriResolver& resolver);

/// Whether the model or a nested one has a <sensor> in a link or a <plugin>: a static model
/// that does is simulated as a static robot, so that they work.
bool carriesSensorsOrPlugins(const SdfModel& model);

/// Whether a joint of the model (or of a nested model) has the world as its parent: such a
/// model does not move as a whole, and is simulated as static.
bool isAnchoredToWorld(const SdfModel& model, std::string* joint_name = nullptr,
                       bool* fixed = nullptr);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_MODEL_H
