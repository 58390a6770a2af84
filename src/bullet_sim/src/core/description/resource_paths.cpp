#include "bullet_sim/description/resource_paths.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>

namespace bullet_sim {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> splitPathList(const char* value) {
  std::vector<std::string> out;
  if (!value) return out;
  std::stringstream in(value);
  std::string entry;
  while (std::getline(in, entry, ':'))
    if (!entry.empty()) out.push_back(entry);
  return out;
}

bool isFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

/// The <name> of a package.xml, or "".
std::string packageName(const fs::path& manifest) {
  std::ifstream in(manifest);
  std::stringstream text;
  text << in.rdbuf();
  static const std::regex name_re("<name>\\s*([^<\\s]+)\\s*</name>");
  std::smatch match;
  const std::string s = text.str();
  return std::regex_search(s, match, name_re) ? match[1].str() : "";
}

/// Records every package under `dir` as rospack does: a folder with a package.xml is a
/// package and is not descended into; folders holding CATKIN_IGNORE are skipped; the
/// first package found with a name wins.
void crawl(const fs::path& dir, int depth, std::map<std::string, std::string>* found) {
  std::error_code ec;
  if (depth > 8 || !fs::is_directory(dir, ec) || fs::exists(dir / "CATKIN_IGNORE", ec)) return;
  if (isFile(dir / "package.xml")) {
    const std::string name = packageName(dir / "package.xml");
    if (!name.empty()) found->emplace(name, dir.string());
    return;
  }
  std::vector<fs::path> children;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec) && it->path().filename().string()[0] != '.')
      children.push_back(it->path());
  std::sort(children.begin(), children.end());
  for (const fs::path& child : children) crawl(child, depth + 1, found);
}

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

std::mutex exported_mutex;
std::shared_future<std::vector<std::string>> exported_model_paths;

}  // namespace

ResourcePaths ResourcePaths::fromEnvironment() {
  ResourcePaths paths;
  paths.model_paths = splitPathList(std::getenv("GAZEBO_MODEL_PATH"));
  paths.package_paths = splitPathList(std::getenv("ROS_PACKAGE_PATH"));
  std::lock_guard<std::mutex> lock(exported_mutex);
  paths.later_model_paths = exported_model_paths;
  return paths;
}

void ResourcePaths::setExportedModelPaths(std::shared_future<std::vector<std::string>> paths) {
  std::lock_guard<std::mutex> lock(exported_mutex);
  exported_model_paths = std::move(paths);
}

UriResolver::UriResolver(ResourcePaths paths) : paths_(std::move(paths)) {}

std::string UriResolver::findPackage(const std::string& name) const {
  if (!packages_crawled_) {
    for (const std::string& root : paths_.package_paths) crawl(root, 0, &package_dirs_);
    packages_crawled_ = true;
  }
  const auto it = package_dirs_.find(name);
  return it == package_dirs_.end() ? "" : it->second;
}

template <class IsWanted>
std::string UriResolver::findInModelRoots(const std::string& relative, IsWanted is_wanted,
                                          std::vector<std::string>* searched) const {
  const auto found_in = [&](const std::string& root) {
    if (searched) searched->push_back(root);
    return is_wanted(fs::path(root) / relative);
  };
  for (const std::string& root : paths_.model_paths)
    if (found_in(root)) return (fs::path(root) / relative).string();
  if (!paths_.later_model_paths.valid()) return "";
  const std::vector<std::string>& first = paths_.model_paths;
  for (const std::string& root : paths_.later_model_paths.get()) {
    if (std::find(first.begin(), first.end(), root) != first.end()) continue;  // seen
    if (found_in(root)) return (fs::path(root) / relative).string();
  }
  return "";
}

std::string UriResolver::findModel(const std::string& name,
                                   std::vector<std::string>* searched) const {
  return findInModelRoots(
      name,
      [](const fs::path& path) {
        std::error_code ec;
        return fs::is_directory(path, ec);
      },
      searched);
}

std::string UriResolver::resolve(const std::string& uri, const std::string& base_dir,
                                 std::vector<std::string>* searched) const {
  if (startsWith(uri, "model://")) return findInModelRoots(uri.substr(8), isFile, searched);
  if (startsWith(uri, "package://")) {
    const std::string rest = uri.substr(10);
    const std::string package = rest.substr(0, rest.find('/'));
    const std::string inside = rest.size() > package.size() ? rest.substr(package.size() + 1) : "";
    if (searched) searched->insert(searched->end(), paths_.package_paths.begin(),
                                   paths_.package_paths.end());
    const std::string dir = findPackage(package);
    if (dir.empty() || !isFile(fs::path(dir) / inside)) return "";
    return (fs::path(dir) / inside).string();
  }
  const std::string path = startsWith(uri, "file://") ? uri.substr(7) : uri;
  fs::path candidate(path);
  if (candidate.is_relative() && !base_dir.empty()) candidate = fs::path(base_dir) / candidate;
  if (searched) searched->push_back(candidate.parent_path().string());
  return isFile(candidate) ? candidate.string() : "";
}

}  // namespace bullet_sim
