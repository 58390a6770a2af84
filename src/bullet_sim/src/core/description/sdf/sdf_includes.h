#ifndef BULLET_SIM_CORE_SDF_INCLUDES_H
#define BULLET_SIM_CORE_SDF_INCLUDES_H

#include <string>
#include <vector>

#include "bullet_sim/description/resource_paths.h"

namespace bullet_sim {

/// The folder holding the built-in copies of Gazebo's stock models `sun` and
/// `ground_plane`, used when no model folder on the path provides them.
std::string builtinModelsDir();

/// The SDF file a model folder's model.config names: the <sdf version=".."> entry with
/// the highest version the reader reads (1.9). Returns "" and sets `problem` (missing or
/// malformed model.config, no usable entry, missing file).
std::string modelSdfFile(const std::string& model_dir, std::string* problem);

/// The SDF file an <include> <uri> names: model://NAME (a model folder, found through
/// `resolver`'s model paths, which may sit deeper as model://set/part; the built-in sun and
/// ground_plane last) or model://NAME/file.sdf, a relative path (from `base_dir`, the folder
/// of the including file), file:// or an absolute path, to a model folder or to a file.
/// Returns "" and sets `problem` (the URI, the folders searched, or what is wrong with the
/// model folder's model.config) when it names nothing readable.
std::string resolveIncludeUri(const std::string& uri, const std::string& base_dir,
                              const UriResolver& resolver, std::string* problem);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_INCLUDES_H
