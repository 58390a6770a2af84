#include "description/material/material_scripts.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

#include "bullet_sim/errors.h"

namespace bullet_sim {
namespace {

namespace fs = std::filesystem;
using Materials = std::vector<OgreMaterial>;

bool isDirectory(const fs::path& path) {
  std::error_code ec;
  return fs::is_directory(path, ec);
}

bool isFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

/// The *.material files of `folder`, in name order.
std::vector<std::string> scriptsIn(const fs::path& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".material" && isFile(it->path()))
      files.push_back(it->path().string());
  std::sort(files.begin(), files.end());
  return files;
}

/// The script files in search order (see findScriptMaterial).
std::vector<std::string> scriptFiles(const std::vector<std::string>& uri_paths,
                                     const std::vector<std::string>& resource_paths) {
  std::vector<std::string> files;
  const auto add_folder = [&](const fs::path& folder) {
    for (std::string& file : scriptsIn(folder)) files.push_back(std::move(file));
  };
  for (const std::string& uri : uri_paths) {
    if (isFile(uri)) files.push_back(uri);
    else add_folder(uri);
  }
  for (const std::string& entry : resource_paths) {
    add_folder(fs::path(entry) / "media" / "materials" / "scripts");
    add_folder(entry);
  }
  return files;
}

/// The folders a texture of `script` is looked up in, in order.
std::vector<fs::path> textureFolders(const std::string& script,
                                     const std::vector<std::string>& uri_paths,
                                     const std::vector<std::string>& resource_paths) {
  std::vector<fs::path> folders;
  for (const std::string& uri : uri_paths)
    if (isDirectory(uri)) folders.emplace_back(uri);
  const fs::path script_folder = fs::path(script).parent_path();
  folders.push_back(script_folder);
  folders.push_back((script_folder / ".." / "textures").lexically_normal());
  for (const std::string& entry : resource_paths) {
    folders.push_back(fs::path(entry) / "media" / "materials" / "textures");
    folders.emplace_back(entry);
  }
  return folders;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw LoadError(path + ": cannot read the material script");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The materials of script `path`, parsed once per version of the file (its time and size).
std::shared_ptr<const Materials> parsedScript(const std::string& path) {
  struct Entry {
    fs::file_time_type time;
    std::uintmax_t size;
    std::shared_ptr<const Materials> materials;
  };
  static std::mutex mutex;
  static std::map<std::string, Entry> cache;
  std::error_code ec;
  const fs::file_time_type time = fs::last_write_time(path, ec);
  const std::uintmax_t size = fs::file_size(path, ec);
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(path);
    if (it != cache.end() && it->second.time == time && it->second.size == size)
      return it->second.materials;
  }
  auto materials = std::make_shared<const Materials>(parseOgreMaterials(readFile(path), path));
  std::lock_guard<std::mutex> lock(mutex);
  cache[path] = Entry{time, size, materials};
  return materials;
}

std::string listed(const std::vector<fs::path>& folders) {
  std::string out;
  for (const fs::path& folder : folders) out += (out.empty() ? "" : ", ") + folder.string();
  return out;
}

/// The path of `material`'s texture, or "" with a warning.
std::string texturePath(const OgreMaterial& material, const std::vector<std::string>& uri_paths,
                        const std::vector<std::string>& resource_paths,
                        std::vector<std::string>* warnings) {
  const std::string& texture = material.texture_unit->texture;
  if (fs::path(texture).is_absolute() && isFile(texture)) return texture;
  const std::vector<fs::path> folders =
      textureFolders(material.script_path, uri_paths, resource_paths);
  for (const fs::path& folder : folders)
    if (isFile(folder / texture)) return (folder / texture).string();
  if (warnings)
    warnings->push_back(material.script_path + ": material '" + material.name + "': texture '" +
                        texture + "' not found (looked in " + listed(folders) +
                        "); drawn in its colour");
  return "";
}

}  // namespace

std::vector<std::string> gazeboResourcePaths() {
  std::vector<std::string> out;
  const char* value = std::getenv("GAZEBO_RESOURCE_PATH");
  std::stringstream in(value ? value : "");
  std::string entry;
  while (std::getline(in, entry, ':'))
    if (!entry.empty()) out.push_back(entry);
  return out;
}

std::optional<ScriptMaterial> findScriptMaterial(const std::string& name,
                                                 const std::vector<std::string>& uri_paths,
                                                 const std::vector<std::string>& resource_paths,
                                                 std::vector<std::string>* warnings) {
  for (const std::string& script : scriptFiles(uri_paths, resource_paths)) {
    const std::shared_ptr<const Materials> materials = parsedScript(script);
    const auto it = std::find_if(materials->begin(), materials->end(),
                                 [&](const OgreMaterial& m) { return m.name == name; });
    if (it == materials->end()) continue;
    ScriptMaterial found{*it, ""};
    if (it->texture_unit)
      found.texture_path = texturePath(*it, uri_paths, resource_paths, warnings);
    return found;
  }
  return std::nullopt;
}

}  // namespace bullet_sim
