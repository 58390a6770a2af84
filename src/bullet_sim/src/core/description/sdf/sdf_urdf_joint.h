#ifndef BULLET_SIM_CORE_SDF_URDF_JOINT_H
#define BULLET_SIM_CORE_SDF_URDF_JOINT_H

#include <string>
#include <vector>

#include <urdf_model/model.h>

#include "description/sdf/sdf_model_entries.h"

namespace bullet_sim {

/// Adds SDF joint `j` between `parent` and `child` to `urdf`: its type (an unsupported one
/// held fixed, with a warning naming `where`), limits, damping and friction. URDF puts a
/// joint at its child link's origin: a joint elsewhere in its child gets an intermediate
/// massless link at the joint, fixed to the child (Bullet merges the two).
void addUrdfJoint(const JointEntry& j, const LinkEntry& parent, const LinkEntry& child,
                  const std::string& where, urdf::ModelInterface* urdf,
                  std::vector<std::string>* warnings);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_URDF_JOINT_H
