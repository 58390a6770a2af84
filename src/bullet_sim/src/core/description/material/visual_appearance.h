#ifndef BULLET_SIM_CORE_VISUAL_APPEARANCE_H
#define BULLET_SIM_CORE_VISUAL_APPEARANCE_H

#include <string>
#include <vector>

#include <Eigen/Core>

#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/types.h"
#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// How an SDF visual looks: its colour and, from a material script, its texture.
struct Appearance {
  Eigen::Vector4f rgba{0.7f, 0.7f, 0.7f, 1.0f};
  TextureRef texture;
};

/// The appearance of `visual` as Gazebo Classic shows it. An explicit <diffuse> gives the
/// colour; a <script> name of Gazebo's stock materials its colour (sdf_util's table); any
/// other script name is looked up in the OGRE scripts of the <script>'s <uri>s (model://,
/// file:// or relative to the folder of the file that defines the visual, files or
/// folders) and of GAZEBO_RESOURCE_PATH: its pass's diffuse (else ambient, else white) and its texture_unit's image, scale and
/// scroll. A name found nowhere, or a texture found nowhere, adds a warning naming it
/// (`where` says whose visual it is) and the visual keeps a colour.
/// @throws LoadError for a script with a syntax error (naming its file and line).
Appearance visualAppearance(const SdfVisual& visual, const std::string& where,
                            const UriResolver& resolver, std::vector<std::string>* warnings);

/// The path a <script> <uri> names, a file or a folder: `model://NAME/rest` in NAME's model
/// folder, `file://PATH` absolute or under a GAZEBO_RESOURCE_PATH entry, otherwise relative
/// to `base_dir`. "" when it names nothing that exists.
std::string resolveScriptUri(const std::string& uri, const std::string& base_dir,
                             const UriResolver& resolver,
                             const std::vector<std::string>& resource_paths);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_VISUAL_APPEARANCE_H
