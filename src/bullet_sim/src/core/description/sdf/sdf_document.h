#ifndef BULLET_SIM_CORE_SDF_DOCUMENT_H
#define BULLET_SIM_CORE_SDF_DOCUMENT_H

#include <memory>
#include <string>
#include <vector>

#include <sdf/sdf.hh>
#include <tinyxml2.h>

#include "bullet_sim/description/resource_paths.h"

namespace bullet_sim {

/// SDF text read by tinyxml2: for what libsdformat's DOM leaves out (a world's <state>), and
/// because libsdformat reports malformed XML only as "Unable to read file" while tinyxml2
/// (the parser it uses) says what and where. `kind` ("world", "model") goes into messages.
/// @throws LoadError naming `source` and tinyxml2's reason.
std::unique_ptr<tinyxml2::XMLDocument> parseSdfXml(const std::string& text,
                                                   const std::string& source,
                                                   const std::string& kind);

/// SDF text (read from `path`, or "" for text from elsewhere) loaded by libsdformat; its
/// <include>s are resolved through `resolver` (built-in sun and ground_plane), relative
/// URIs from the folder of `path`.
/// libsdformat's complaint about invalid link inertia goes to `warnings` (static links in
/// worlds saved by Gazebo have nan moments; movable links are checked when converted).
/// @throws LoadError naming `source`: an include that cannot be resolved (with the URI and
/// the folders searched, or what is wrong with its model.config), libsdformat's errors.
std::unique_ptr<sdf::Root> loadSdfRoot(const std::string& text, const std::string& source,
                                       const std::string& path, const UriResolver& resolver,
                                       const std::string& kind,
                                       std::vector<std::string>* warnings);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_DOCUMENT_H
