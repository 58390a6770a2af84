#ifndef BULLET_SIM_TEST_PLUGIN_PARAMS_H
#define BULLET_SIM_TEST_PLUGIN_PARAMS_H

#include <string>
#include <utility>
#include <vector>

namespace bullet_sim_test {

/// One parameter of a plugin: its element's path below <plugin> ("wheelSeparation",
/// "ros/namespace", an attribute as "remapping@from") and its text, trimmed.
using PluginParameter = std::pair<std::string, std::string>;

/// The parameters of a printed <plugin> element, in document order; a child with
/// children of its own gives theirs, not its text. Sets `problem` when `xml` is not one
/// well-formed element.
std::vector<PluginParameter> pluginParameters(const std::string& xml, std::string* problem);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_PLUGIN_PARAMS_H
