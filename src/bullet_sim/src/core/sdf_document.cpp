#include "sdf_document.h"

#include <filesystem>

#include "bullet_sim/errors.h"
#include "bullet_sim/robot_spec.h"
#include "sdf_includes.h"
#include "sdf_model.h"
#include "sdf_util.h"

namespace bullet_sim {

namespace fs = std::filesystem;

std::unique_ptr<tinyxml2::XMLDocument> parseSdfXml(const std::string& text,
                                                   const std::string& source,
                                                   const std::string& kind) {
  auto doc = std::make_unique<tinyxml2::XMLDocument>();
  if (doc->Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    throw LoadError(source + ": invalid SDF " + kind + ": malformed XML: " + doc->ErrorStr());
  }
  return doc;
}

std::unique_ptr<sdf::Root> loadSdfRoot(const std::string& text, const std::string& source,
                                       const std::string& path, const UriResolver& resolver,
                                       const std::string& kind) {
  IncludeResolver includes(resolver, path.empty() ? "" : fs::path(path).parent_path().string());
  auto root = std::make_unique<sdf::Root>();
  // Loading by path lets libsdformat record each element's file (for relative mesh URIs).
  const sdf::Errors errors = path.empty() ? root->LoadSdfString(text, includes.parserConfig())
                                          : root->Load(path, includes.parserConfig());
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
  const auto root = loadSdfRoot(sdf_xml, source_name, "", resolver, "model");
  const sdf::Model* model = root->Model();
  if (!model) throw LoadError(source_name + ": no <model> element (an SDF model is expected)");
  return parseSdfModel(*model, source_name, resolver);
}

}  // namespace bullet_sim
