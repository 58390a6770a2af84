#ifndef BULLET_SIM_CORE_PLUGIN_PARAMETERS_H
#define BULLET_SIM_CORE_PLUGIN_PARAMETERS_H

#include <string>
#include <vector>

#include <tinyxml2.h>

namespace bullet_sim {

/// Warns about the children of a Gazebo ROS `<plugin>` that the plugin does not take, so
/// that a misspelled parameter (`<wheelSeperation>`) is not silently left at its default:
/// one warning per unknown element, naming `where`, the element and the nearest known
/// parameter when one is close. Parameters Gazebo's plugin takes but the simulator does not
/// use are known (no warning). A plugin file this does not know is not checked.
void warnUnknownPluginParameters(const tinyxml2::XMLElement* plugin, const std::string& file,
                                 const std::string& where, std::vector<std::string>* warnings);

/// The known parameter nearest to `name` (edit distance at most a third of its length,
/// ignoring case), or "" when none is that close.
std::string nearestName(const std::string& name, const std::vector<std::string>& known);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PLUGIN_PARAMETERS_H
