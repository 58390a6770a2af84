#ifndef BULLET_SIM_CORE_MATERIAL_SCRIPTS_H
#define BULLET_SIM_CORE_MATERIAL_SCRIPTS_H

#include <optional>
#include <string>
#include <vector>

#include "description/material/ogre_material.h"

namespace bullet_sim {

/// A material found in an OGRE material script, with its texture file.
struct ScriptMaterial {
  OgreMaterial material;
  /// The texture_unit's image file; "" when the material has no texture_unit or the file
  /// is found nowhere.
  std::string texture_path;
};

/// The entries of GAZEBO_RESOURCE_PATH (':'-separated, empty entries skipped).
std::vector<std::string> gazeboResourcePaths();

/// Looks up material `name` of an SDF `<material><script>` as Gazebo Classic's resource
/// locations do. Scripts: each of `uri_paths` (the `<uri>`s resolved to paths: a .material
/// file, or a folder whose *.material files are read in name order), then for each of
/// `resource_paths` (GAZEBO_RESOURCE_PATH) its media/materials/scripts folder and the entry
/// itself; the first definition of `name` wins. Texture: looked up by file name in the
/// folders of `uri_paths`, the script's folder, the script's ../textures, then each
/// resource path's media/materials/textures and the entry itself. A texture found nowhere
/// adds one warning to `warnings` (if given) and leaves texture_path "". Returns nullopt
/// when no script defines `name`. A script with a syntax error throws LoadError. Parsed
/// scripts are kept per file (re-read when the file changes); safe to call from threads.
std::optional<ScriptMaterial> findScriptMaterial(const std::string& name,
                                                 const std::vector<std::string>& uri_paths,
                                                 const std::vector<std::string>& resource_paths,
                                                 std::vector<std::string>* warnings);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_MATERIAL_SCRIPTS_H
