#include "description/sdf/sdf_reader.h"

#include <regex>

#include "bullet_sim/errors.h"
#include "description/sdf/sdf_read_link.h"
#include "description/sdf/sdf_read_model.h"
#include "description/sdf/sdf_read_world.h"

namespace bullet_sim {
namespace {

/// "1.6" -> {1, 6}; nullopt for anything else.
std::optional<SdfVersion> versionOf(const std::string& text) {
  static const std::regex kVersion("([0-9]{1,6})\\.([0-9]{1,6})");
  std::smatch m;
  if (!std::regex_match(text, m, kVersion)) return std::nullopt;
  return SdfVersion{std::stoi(m[1]), std::stoi(m[2])};
}

/// Checks <sdf version>: numbers Gazebo reads (1.0 to 1.9).
void checkSdfVersion(const tinyxml2::XMLDocument& doc, const std::string& source,
                     const std::string& kind) {
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  if (!sdf) throw LoadError(source + ": invalid SDF " + kind + ": no <sdf> element");
  const char* version = sdf->Attribute("version");
  if (!version) {
    throw LoadError(source + ":" + std::to_string(sdf->GetLineNum()) + ": invalid SDF " + kind +
                    ": <sdf> has no version attribute");
  }
  if (!versionOf(version)) {
    throw LoadError(source + ": invalid SDF " + kind + ": <sdf version=\"" + version +
                    "\">: not a version number such as \"1.6\"");
  }
  if (!isReadableSdfVersion(version)) {
    throw LoadError(source + ": invalid SDF " + kind + ": <sdf version=\"" + version +
                    "\">: the simulator reads SDF 1.0 to 1.9");
  }
}

}  // namespace

bool isReadableSdfVersion(const std::string& version) {
  const auto v = versionOf(version);
  return v && v->major == 1 && v->minor <= 9;
}

SdfVersion sdfVersionOf(const tinyxml2::XMLDocument& doc) {
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const char* text = sdf ? sdf->Attribute("version") : nullptr;
  const auto v = text ? versionOf(text) : std::nullopt;
  return v ? *v : SdfVersion{};
}

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

SdfDocument readSdf(const tinyxml2::XMLDocument& doc, const std::string& source,
                    const std::string& path, const UriResolver& resolver,
                    std::vector<std::string>* warnings) {
  SdfReadContext context(resolver, warnings);
  const SdfValues& values = context.valuesOf(path.empty() ? source : path, sdfVersionOf(doc));
  SdfDocument out;
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  out.version = sdf && sdf->Attribute("version") ? sdf->Attribute("version") : "";
  if (!sdf) return out;
  if (const tinyxml2::XMLElement* world = sdf->FirstChildElement("world")) {
    out.world = readSdfWorld(world, values, &context);
  } else if (const tinyxml2::XMLElement* model = sdf->FirstChildElement("model")) {
    ReadModel read = readSdfModel(model, values, true, {}, &context);
    read.model.T_parent_model = read.pose.T;
    out.model = std::move(read.model);
  } else if (const tinyxml2::XMLElement* light = sdf->FirstChildElement("light")) {
    out.light = readSdfLight(light, values, nullptr);
  }
  return out;
}

namespace {

/// The link `wanted` ("" = the first, else the first nested model's) of `m`, scoped and
/// posed in m's frame.
std::optional<std::pair<std::string, Eigen::Isometry3d>> findCanonical(const SdfModel& m,
                                                                       const std::string& wanted) {
  for (const SdfLink& l : m.links) {
    if (wanted.empty() || l.name == wanted) return std::make_pair(l.name, l.T_model_link);
  }
  const auto sep = wanted.find("::");
  for (const SdfModel& nested : m.models) {
    if (!wanted.empty() && (sep == std::string::npos || wanted.substr(0, sep) != nested.name)) {
      continue;
    }
    const auto found = findCanonical(nested, wanted.empty() ? "" : wanted.substr(sep + 2));
    if (found) {
      return std::make_pair(nested.name + "::" + found->first,
                            nested.T_parent_model * found->second);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::pair<std::string, Eigen::Isometry3d>> SdfModel::canonicalLink() const {
  return findCanonical(*this, canonical_link);
}

}  // namespace bullet_sim
