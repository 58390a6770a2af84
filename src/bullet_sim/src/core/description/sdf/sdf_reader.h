#ifndef BULLET_SIM_CORE_SDF_READER_H
#define BULLET_SIM_CORE_SDF_READER_H

#include <string>
#include <vector>

#include <tinyxml2.h>

#include "bullet_sim/description/resource_paths.h"
#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// The SDF versions read: 1.0 to 1.9 (those before 1.4 as 1.4; Gazebo classic 11 writes
/// 1.4 to 1.7).
bool isReadableSdfVersion(const std::string& version);

/// SDF text parsed by tinyxml2, its <sdf version> checked. `kind` ("world", "model") goes
/// into messages.
/// @throws LoadError naming `source` and tinyxml2's reason and line, or the version.
std::unique_ptr<tinyxml2::XMLDocument> parseSdfXml(const std::string& text,
                                                   const std::string& source,
                                                   const std::string& kind);

/// Reads a parsed SDF document (`source` names it in messages; `path` is its file, or ""
/// for text from elsewhere, whose relative URIs are taken from the current folder).
/// <include>s are resolved through `resolver` (model://, relative and file:// URIs; the
/// built-in sun and ground_plane when no model folder has them) and read as their own
/// <sdf version> says. What Gazebo accepts and goes on without (an unknown element, the
/// <script> shorthand) adds a warning to `warnings`.
/// @throws LoadError naming the file, line and element: a malformed value, a missing
/// required element or attribute, an include that cannot be resolved (the URI and the
/// folders searched), a pose relative to a frame that does not exist or a frame cycle.
SdfDocument readSdf(const tinyxml2::XMLDocument& doc, const std::string& source,
                    const std::string& path, const UriResolver& resolver,
                    std::vector<std::string>* warnings);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_READER_H
