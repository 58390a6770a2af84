#include "description/material/visual_appearance.h"

#include <filesystem>

#include "description/material/gazebo_materials.h"
#include "description/material/material_scripts.h"
#include "description/sdf/sdf_util.h"

namespace bullet_sim {
namespace {

namespace fs = std::filesystem;

bool pathExists(const fs::path& path) {
  std::error_code ec;
  return fs::exists(path, ec);
}

/// The UV transform of an OGRE texture_unit: OGRE scales about the image centre
/// (u' = (u - 0.5) / scale + 0.5), then scrolls (u' += scroll).
TextureRef textureOf(const ScriptMaterial& found) {
  TextureRef texture;
  texture.path = found.texture_path;
  const OgreTextureUnit& unit = *found.material.texture_unit;
  for (int axis = 0; axis < 2; ++axis) {
    const double scale = unit.scale[axis] != 0 ? unit.scale[axis] : 1.0;
    texture.uv_scale[axis] = static_cast<float>(1.0 / scale);
    texture.uv_offset[axis] = static_cast<float>(0.5 - 0.5 / scale + unit.scroll[axis]);
  }
  return texture;
}

/// The folder a material's relative script <uri>s start from: that of the file that
/// defines the visual, "" when that is no file.
std::string scriptBaseDir(const SdfOrigin& origin) {
  std::error_code ec;
  return fs::is_regular_file(origin.file, ec) ? fs::path(origin.file).parent_path().string() : "";
}

/// A script material's colour: its pass's diffuse, else its ambient, else white.
Eigen::Vector4f scriptColour(const OgreMaterial& m) {
  return m.diffuse ? *m.diffuse : m.ambient ? *m.ambient : Eigen::Vector4f::Ones();
}

/// The script material of `material`'s script name, looked up in its <uri>s and
/// GAZEBO_RESOURCE_PATH; nullopt, with a warning unless it is a stock material, when no
/// script defines it.
std::optional<ScriptMaterial> lookUpScript(const SdfMaterial& material, const SdfOrigin& origin,
                                           const std::string& where, const UriResolver& resolver,
                                           std::vector<std::string>* warnings) {
  const std::string& name = material.script_name;
  const std::vector<std::string> resource_paths = gazeboResourcePaths();
  const std::string base_dir = scriptBaseDir(origin);
  std::vector<std::string> uri_paths;
  for (const std::string& uri : material.script_uris) {
    const std::string path = resolveScriptUri(uri, base_dir, resolver, resource_paths);
    if (!path.empty()) uri_paths.push_back(path);
  }
  std::vector<std::string> lookup_warnings;
  auto found = findScriptMaterial(name, uri_paths, resource_paths, &lookup_warnings);
  for (const std::string& w : lookup_warnings) warnings->push_back(where + ": " + w);
  if (!found && !gazeboMaterialColour(name)) {
    warnings->push_back(where + ": material script '" + name +
                        "' is not one of Gazebo's stock materials nor in any script of its "
                        "<uri>s or GAZEBO_RESOURCE_PATH: drawn grey");
  }
  return found;
}

}  // namespace

std::string resolveScriptUri(const std::string& uri, const std::string& base_dir,
                             const UriResolver& resolver,
                             const std::vector<std::string>& resource_paths) {
  const std::string model_scheme = "model://", file_scheme = "file://";
  if (uri.rfind(model_scheme, 0) == 0) {
    const std::string rest = uri.substr(model_scheme.size());
    const std::string name = rest.substr(0, rest.find('/'));
    const std::string dir = resolver.findModel(name);
    if (dir.empty()) return "";
    const fs::path path = rest.find('/') == std::string::npos
                              ? fs::path(dir)
                              : fs::path(dir) / rest.substr(rest.find('/') + 1);
    return pathExists(path) ? path.string() : "";
  }
  const std::string path = uri.rfind(file_scheme, 0) == 0 ? uri.substr(file_scheme.size()) : uri;
  if (fs::path(path).is_absolute()) return pathExists(path) ? path : "";
  if (uri.rfind(file_scheme, 0) == 0) {
    for (const std::string& root : resource_paths) {
      if (pathExists(fs::path(root) / path)) return (fs::path(root) / path).string();
    }
    return "";
  }
  const fs::path relative = fs::path(base_dir.empty() ? "." : base_dir) / path;
  return pathExists(relative) ? relative.string() : "";
}

Appearance visualAppearance(const SdfVisual& visual, const std::string& where,
                            const UriResolver& resolver, std::vector<std::string>* warnings) {
  Appearance out;
  out.rgba = visualColour(visual, where, nullptr);
  if (!visual.material || visual.material->script_name.empty()) return out;
  const SdfMaterial& material = *visual.material;
  const bool explicit_diffuse = material.diffuse.has_value();
  if (gazeboMaterialColour(material.script_name) && !explicit_diffuse) return out;  // stock
  const auto found = lookUpScript(material, visual.origin, where, resolver, warnings);
  if (!found) return out;
  if (!explicit_diffuse) out.rgba = scriptColour(found->material);
  if (found->material.texture_unit && !found->texture_path.empty()) out.texture = textureOf(*found);
  return out;
}

}  // namespace bullet_sim
