#include "description/sdf/sdf_includes.h"

#include <filesystem>
#include <sstream>

#include <tinyxml2.h>

namespace bullet_sim {
namespace {

namespace fs = std::filesystem;

/// "1.6" -> {1, 6}; {-1, -1} when it is not a version.
std::pair<int, int> parseVersion(const std::string& text) {
  std::istringstream in(text);
  int major = -1, minor = -1;
  char dot = 0;
  if (!(in >> major >> dot >> minor) || dot != '.') return {-1, -1};
  return {major, minor};
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out.empty() ? "(none)" : out;
}

bool isBuiltin(const std::string& name) { return name == "sun" || name == "ground_plane"; }

/// The <model> element of the model.config `config`, read into `doc`; null with *problem
/// saying why when the file is not XML or has none.
const tinyxml2::XMLElement* modelConfigRoot(const fs::path& config, tinyxml2::XMLDocument* doc,
                                            std::string* problem) {
  if (doc->LoadFile(config.c_str()) != tinyxml2::XML_SUCCESS) {
    *problem = config.string() + ": malformed XML: " + doc->ErrorStr();
    return nullptr;
  }
  const tinyxml2::XMLElement* model = doc->FirstChildElement("model");
  if (!model) *problem = config.string() + ": no <model> element";
  return model;
}

/// A model.config's <sdf version="..">FILE</sdf> entry.
struct SdfEntry {
  std::pair<int, int> version{-1, -1};
  std::string file;  ///< "" when no entry is of a version the reader reads
  std::string seen;  ///< every version given, for messages ("?" for none)
};

/// The entry of the newest version that the reader reads, as Gazebo picks it.
SdfEntry newestReadableEntry(const tinyxml2::XMLElement& model) {
  const std::pair<int, int> supported{1, 9};
  SdfEntry best;
  for (const tinyxml2::XMLElement* s = model.FirstChildElement("sdf"); s;
       s = s->NextSiblingElement("sdf")) {
    const char* version_text = s->Attribute("version");
    const std::pair<int, int> version = parseVersion(version_text ? version_text : "");
    best.seen += std::string(best.seen.empty() ? "" : ", ") + (version_text ? version_text : "?");
    if (version.first < 0 || version > supported || version <= best.version || !s->GetText()) {
      continue;
    }
    best.version = version;
    best.file = s->GetText();
  }
  return best;
}

}  // namespace

std::string builtinModelsDir() { return BULLET_SIM_BUILTIN_MODELS_DIR; }

std::string modelSdfFile(const std::string& model_dir, std::string* problem) {
  const fs::path config = fs::path(model_dir) / "model.config";
  std::error_code ec;
  if (!fs::is_regular_file(config, ec)) {
    *problem = "model folder " + model_dir + " has no model.config";
    return "";
  }
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* model = modelConfigRoot(config, &doc, problem);
  if (!model) return "";
  const SdfEntry entry = newestReadableEntry(*model);
  if (entry.file.empty()) {
    *problem = config.string() + ": no <sdf version=\"..\"> entry of a version the " +
               "simulator reads (1.0 to 1.9; versions given: " +
               (entry.seen.empty() ? "none" : entry.seen) + ")";
    return "";
  }
  const fs::path file = fs::path(model_dir) / entry.file;
  if (!fs::is_regular_file(file, ec)) {
    *problem = config.string() + ": <sdf version=\"" + std::to_string(entry.version.first) +
               "." + std::to_string(entry.version.second) + "\"> names " + file.string() +
               ", which does not exist";
    return "";
  }
  return file.string();
}

namespace {

/// model://NAME names a model folder, which may sit deeper (model://set/part) as Gazebo
/// allows; model://NAME/file.sdf names a file in one.
std::string resolveModelUri(const std::string& uri, const UriResolver& resolver,
                            std::string* problem) {
  const std::string rest = uri.substr(8);
  std::vector<std::string> searched;
  std::string dir = resolver.findModel(rest, &searched);
  if (dir.empty() && isBuiltin(rest)) dir = (fs::path(builtinModelsDir()) / rest).string();
  if (dir.empty()) {
    const std::string file = resolver.resolve(uri, "");
    if (!file.empty()) return file;
    *problem = "<uri>" + uri + "</uri>: model '" + rest +
               "' not found in the model folders (GAZEBO_MODEL_PATH): " + join(searched) +
               "; built in are only sun and ground_plane";
    return "";
  }
  const std::string file = modelSdfFile(dir, problem);
  if (file.empty()) *problem = "<uri>" + uri + "</uri>: " + *problem;
  return file;
}

}  // namespace

std::string resolveIncludeUri(const std::string& uri, const std::string& base_dir,
                              const UriResolver& resolver, std::string* problem) {
  if (uri.compare(0, 8, "model://") == 0) return resolveModelUri(uri, resolver, problem);
  if (uri.compare(0, 10, "package://") == 0) {
    const std::string file = resolver.resolve(uri, base_dir);
    if (file.empty()) *problem = "<uri>" + uri + "</uri>: no such file";
    return file;
  }
  fs::path path(uri.compare(0, 7, "file://") == 0 ? uri.substr(7) : uri);
  if (path.is_relative() && !base_dir.empty()) path = fs::path(base_dir) / path;
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return path.string();
  if (!fs::is_directory(path, ec)) {
    *problem = "<uri>" + uri + "</uri>: no such file or model folder (" +
               path.string() + ")";
    return "";
  }
  const std::string file = modelSdfFile(path.string(), problem);
  if (file.empty()) *problem = "<uri>" + uri + "</uri>: " + *problem;
  return file;
}

}  // namespace bullet_sim
