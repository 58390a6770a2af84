#ifndef BULLET_SIM_CORE_GAZEBO_EXTENSIONS_H
#define BULLET_SIM_CORE_GAZEBO_EXTENSIONS_H

#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// Reads the <gazebo> extension tags of a URDF document (surfaces, sensors,
/// plugins, material scripts) into `spec`; unsupported sensors and plugins become
/// warnings. A link's <material> recolours its visuals: spec->visuals must be filled.
/// @throws LoadError on malformed values.
void parseGazeboExtensions(const std::string& urdf_xml, const std::string& source,
                           RobotSpec* spec);

/// A <sensor> of an SDF model's link, as XML text; its own <pose> is replaced by
/// `pose_in_link` (the SDF reader resolves relative_to and frames). `where` names the
/// model, link and sensor in messages.
struct SdfSensorText {
  std::string xml, link, where;
  Pose3 pose_in_link;
};

/// A model-level <plugin> of an SDF model, as XML text; `where` names the model.
struct SdfPluginText {
  std::string xml, where;
};

/// Reads the sensors and model plugins of an SDF model into `spec` through the same
/// readers as a URDF's <gazebo> blocks (a <gazebo> block holds SDF): a sensor family's
/// plugin, unsupported ones as warnings. `source` names the file in messages.
/// @throws LoadError on malformed values.
void readSdfModelExtensions(const std::vector<SdfSensorText>& sensors,
                            const std::vector<SdfPluginText>& plugins,
                            const std::string& source, RobotSpec* spec);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_GAZEBO_EXTENSIONS_H
