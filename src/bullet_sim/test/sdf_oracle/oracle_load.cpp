// The oracle's entry: a file loaded by sdf::Root with <include> URIs found through the
// simulator's UriResolver, then converted kind by kind (oracle_parts.h).
#include <filesystem>

#include "oracle_parts.h"

namespace bullet_sim_test {

namespace fs = std::filesystem;

namespace {

/// Answers libsdformat's find callback for an <include> URI. A model folder is returned
/// as a folder: libsdformat then reads its model.config and picks the SDF file itself.
class IncludeFinder {
 public:
  IncludeFinder(const bullet_sim::UriResolver& resolver, std::string base_dir,
                std::string builtin_models_dir)
      : resolver_(resolver),
        base_dir_(std::move(base_dir)),
        builtin_dir_(std::move(builtin_models_dir)) {}

  std::string operator()(const std::string& uri) const {
    const std::string scheme = "model://";
    if (uri.compare(0, scheme.size(), scheme) != 0) return fileOrFolder(uri);
    const std::string name = uri.substr(scheme.size());
    const std::string dir = resolver_.findModel(name);
    if (!dir.empty()) return dir;
    if (name == "sun" || name == "ground_plane") return (fs::path(builtin_dir_) / name).string();
    // model://NAME/file.sdf: a file inside a model folder.
    return resolver_.resolve(uri, base_dir_);
  }

 private:
  /// A file through the resolver; else a model folder (libsdformat reads its
  /// model.config), relative to the including file's folder.
  std::string fileOrFolder(const std::string& uri) const {
    const std::string file = resolver_.resolve(uri, base_dir_);
    if (!file.empty()) return file;
    const fs::path path(uri.compare(0, 7, "file://") == 0 ? uri.substr(7) : uri);
    const fs::path dir = path.is_relative() ? fs::path(base_dir_) / path : path;
    std::error_code ec;
    return fs::is_directory(dir, ec) ? dir.string() : "";
  }

  const bullet_sim::UriResolver& resolver_;
  std::string base_dir_, builtin_dir_;
};

/// Why libsdformat 12's error `e` is one Gazebo classic does not have, or "" when it is
/// not.
std::string setAsideReason(const sdf::Error& e) {
  if (e.Code() == sdf::ErrorCode::LINK_INERTIA_INVALID) {
    return "libsdformat's inertia check, which Gazebo classic does not make";
  }
  if (e.Message().rfind("A <script> element is missing a child <", 0) == 0) {
    return "a <script> without <uri> or <name>, which Gazebo classic reads";
  }
  if (e.Message().rfind("Camera sensor <image><format> has invalid value of ", 0) == 0) {
    return "a pixel format sdf::Camera does not list, which Gazebo classic's camera reads";
  }
  return "";
}

/// Root::Load's errors into `result`: those Gazebo classic does not have set aside, with
/// the "Failed to load a world." they alone cause.
void sortErrors(const sdf::Errors& errors, const std::string& path, OracleResult* result) {
  sdf::Errors others;
  for (const sdf::Error& e : errors) {
    const std::string why = setAsideReason(e);
    if (why.empty()) {
      others.push_back(e);
    } else {
      result->set_aside.push_back(why + ": " + oracle::formatError(e, path));
    }
  }
  const bool only_set_aside = others.size() == 1 && !result->set_aside.empty() &&
                              others.front().Code() == sdf::ErrorCode::ELEMENT_INVALID &&
                              others.front().Message() == "Failed to load a world.";
  if (!only_set_aside) oracle::appendErrors(others, path, &result->errors);
}

}  // namespace

OracleResult readWithLibsdformat(const std::string& path, const bullet_sim::UriResolver& resolver,
                                 const std::string& builtin_models_dir) {
  OracleResult result;
  sdf::ParserConfig config;
  config.SetFindCallback(
      IncludeFinder(resolver, fs::path(path).parent_path().string(), builtin_models_dir));
  sdf::Root root;
  sortErrors(root.Load(path, config), path, &result);
  if (root.Element()) result.document.version = root.Element()->OriginalVersion();
  if (root.WorldCount() > 0) {
    result.document.world = oracle::worldOf(*root.WorldByIndex(0), &result);
  } else if (root.Model()) {
    result.document.model = oracle::modelOf(*root.Model(), "model", &result);
  } else if (root.Light()) {
    result.document.light = oracle::lightOf(*root.Light(), false, &result.errors);
  }
  if (oracle::unflattensNames(result.document.version)) {
    if (result.document.world) {
      for (bullet_sim::SdfModel& m : result.document.world->models) oracle::flattenConverted(&m);
    }
    if (result.document.model) oracle::flattenConverted(&*result.document.model);
  }
  return result;
}

}  // namespace bullet_sim_test
