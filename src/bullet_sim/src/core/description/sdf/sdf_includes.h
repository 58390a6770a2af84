#ifndef BULLET_SIM_CORE_SDF_INCLUDES_H
#define BULLET_SIM_CORE_SDF_INCLUDES_H

#include <string>
#include <vector>

#include <sdf/sdf.hh>

#include "bullet_sim/description/resource_paths.h"

namespace bullet_sim {

/// The folder holding the built-in copies of Gazebo's stock models `sun` and
/// `ground_plane`, used when no model folder on the path provides them.
std::string builtinModelsDir();

/// The SDF file a model folder's model.config names: the <sdf version=".."> entry with
/// the highest version libsdformat reads. Returns "" and sets `problem` (missing or
/// malformed model.config, no usable entry, missing file).
std::string modelSdfFile(const std::string& model_dir, std::string* problem);

/// Answers libsdformat's questions for the URIs of <include> elements (model://NAME,
/// relative and absolute paths) through a UriResolver, and remembers, for every URI it
/// could not answer, why: libsdformat itself only says "Unable to find uri".
class IncludeResolver {
 public:
  /// `base_dir`: folder of the file being loaded, for relative URIs.
  IncludeResolver(const UriResolver& resolver, std::string base_dir);
  IncludeResolver(const IncludeResolver&) = delete;
  IncludeResolver& operator=(const IncludeResolver&) = delete;

  /// A parser configuration whose find callback asks this object (which must outlive it).
  sdf::ParserConfig parserConfig();
  /// One message per URI that could not be resolved, in the order asked.
  const std::vector<std::string>& failures() const { return failures_; }

 private:
  std::string find(const std::string& uri);
  std::string findModelUri(const std::string& uri);

  const UriResolver& resolver_;
  std::string base_dir_;
  std::vector<std::string> failures_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_INCLUDES_H
