#include "description/sdf/sdf_read_context.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bullet_sim/errors.h"
#include "description/sdf/sdf_includes.h"
#include "description/sdf/sdf_reader.h"

namespace bullet_sim {

namespace fs = std::filesystem;

const SdfValues& SdfReadContext::valuesOf(const std::string& file, SdfVersion version) {
  values_.emplace_back(file, version);
  return values_.back();
}

SdfReadContext::Included SdfReadContext::include(const tinyxml2::XMLElement* include,
                                                 const SdfValues& values) {
  const tinyxml2::XMLElement* uri_element = include->FirstChildElement("uri");
  if (!uri_element) values.fail(include, "the required element <uri> is missing");
  const std::string uri = SdfValues::text(uri_element);
  std::error_code ec;
  const std::string base_dir = fs::is_regular_file(values.file(), ec)
                                   ? fs::path(values.file()).parent_path().string()
                                   : "";
  std::string problem;
  const std::string file = resolveIncludeUri(uri, base_dir, resolver_, &problem);
  if (file.empty()) throw LoadError(values.where(include) + ": " + problem);
  if (std::find(stack_.begin(), stack_.end(), file) != stack_.end()) {
    values.fail(include, "<uri>" + uri + "</uri> includes " + file + ", which is being read: " +
                             "an include cycle");
  }
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) values.fail(include, "cannot read " + file);
  try {
    documents_.push_back(parseSdfXml(text.str(), file, "model"));
  } catch (const LoadError& e) {
    values.fail(include, "<uri>" + uri + "</uri>: " + e.what());
  }
  const tinyxml2::XMLDocument& doc = *documents_.back();
  const tinyxml2::XMLElement* root = doc.FirstChildElement("sdf")->FirstChildElement();
  if (!root) values.fail(include, file + " has nothing in its <sdf> element to include");
  stack_.push_back(file);
  return {root, &valuesOf(file, sdfVersionOf(doc))};
}

}  // namespace bullet_sim
