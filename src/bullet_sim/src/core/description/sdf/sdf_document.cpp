#include "description/sdf/sdf_document.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <regex>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "description/sdf/sdf_includes.h"
#include "description/sdf/sdf_model.h"
#include "description/sdf/sdf_util.h"

namespace bullet_sim {

namespace fs = std::filesystem;

namespace {

/// libsdformat hands <sdf version> to ignition::math::SemanticVersion, which throws
/// std::invalid_argument or std::out_of_range from std::stoi for anything that is not
/// numbers separated by dots ("1.;", "1.99999999999"), so the version is checked first.
void checkSdfVersion(const tinyxml2::XMLDocument& doc, const std::string& source,
                     const std::string& kind) {
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const char* version = sdf ? sdf->Attribute("version") : nullptr;
  static const std::regex kVersion("[0-9]{1,6}(\\.[0-9]{1,6}){0,2}");
  if (version && !std::regex_match(version, kVersion)) {
    throw LoadError(source + ": invalid SDF " + kind + ": <sdf version=\"" + version +
                    "\">: not a version number such as \"1.6\"");
  }
}

}  // namespace

std::unique_ptr<tinyxml2::XMLDocument> parseSdfXml(const std::string& text,
                                                   const std::string& source,
                                                   const std::string& kind) {
  auto doc = std::make_unique<tinyxml2::XMLDocument>();
  if (doc->Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    throw LoadError(source + ": invalid SDF " + kind + ": malformed XML: " + doc->ErrorStr());
  }
  checkSdfVersion(*doc, source, kind);
  return doc;
}

std::unique_ptr<sdf::Root> loadSdfRoot(const std::string& text, const std::string& source,
                                       const std::string& path, const UriResolver& resolver,
                                       const std::string& kind,
                                       std::vector<std::string>* warnings) {
  IncludeResolver includes(resolver, path.empty() ? "" : fs::path(path).parent_path().string());
  auto root = std::make_unique<sdf::Root>();
  // Loading by path lets libsdformat record each element's file (for relative mesh URIs).
  sdf::Errors errors;
  try {
    errors = path.empty() ? root->LoadSdfString(text, includes.parserConfig())
                          : root->Load(path, includes.parserConfig());
  } catch (const std::exception& e) {
    // The same std::stoi throws for an included model file's <sdf version>, which
    // checkSdfVersion does not see.
    throw LoadError(source + ": invalid SDF " + kind + ": libsdformat threw '" + e.what() +
                    "' reading it or its includes");
  }
  // Worlds saved by Gazebo give static links mass 0 and nan moments; Gazebo loads them, and
  // a static link's inertia is never used. Movable links are checked where they are built.
  const auto inertia = std::stable_partition(errors.begin(), errors.end(), [](const sdf::Error& e) {
    return e.Code() != sdf::ErrorCode::LINK_INERTIA_INVALID;
  });
  for (auto e = inertia; e != errors.end(); ++e) {
    warnings->push_back(source + ": " + e->Message() + " (ignored for a static model)");
  }
  const bool had_inertia_errors = inertia != errors.end();
  errors.erase(inertia, errors.end());
  // libsdformat then adds "Failed to load a world." (the world is loaded all the same).
  const bool only_follow_ups = std::all_of(errors.begin(), errors.end(), [](const sdf::Error& e) {
    return e.Message().rfind("Failed to load a ", 0) == 0;
  });
  if (had_inertia_errors && only_follow_ups) errors.clear();
  if (!includes.failures().empty()) {
    std::string message;
    for (const std::string& f : includes.failures()) message += (message.empty() ? "" : "; ") + f;
    throw LoadError(source + ": " + message);
  }
  if (!errors.empty()) throw LoadError(source + ": invalid SDF " + kind + ": " + describe(errors));
  return root;
}

RobotSpec parseSdfModelString(const std::string& sdf_xml, const std::string& source_name,
                              const UriResolver& resolver) {
  parseSdfXml(sdf_xml, source_name, "model");
  std::vector<std::string> warnings;
  const auto root = loadSdfRoot(sdf_xml, source_name, "", resolver, "model", &warnings);
  const sdf::Model* model = root->Model();
  if (!model) throw LoadError(source_name + ": no <model> element (an SDF model is expected)");
  RobotSpec spec = parseSdfModel(*model, source_name, resolver);
  spec.warnings.insert(spec.warnings.begin(), warnings.begin(), warnings.end());
  return spec;
}

RobotSpec parseSdfModelString(const std::string& sdf_xml, const std::string& source_name) {
  return parseSdfModelString(sdf_xml, source_name, UriResolver(ResourcePaths::fromEnvironment()));
}

}  // namespace bullet_sim
