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

/// The <uri>s of the visual's <material><script>, as written.
std::vector<std::string> scriptUris(const sdf::Material& material) {
  std::vector<std::string> uris;
  const sdf::ElementPtr element = material.Element();
  if (!element || !element->HasElement("script")) return uris;
  const sdf::ElementPtr script = element->GetElement("script");
  for (sdf::ElementPtr uri = script->HasElement("uri") ? script->GetElement("uri") : nullptr; uri;
       uri = uri->GetNextElement("uri")) {
    uris.push_back(uri->Get<std::string>());
  }
  return uris;
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

Appearance visualAppearance(const sdf::Visual& visual, const std::string& where,
                            const std::string& source, const UriResolver& resolver,
                            std::vector<std::string>* warnings) {
  Appearance out;
  out.rgba = visualColour(visual, where, nullptr);
  const sdf::Material* material = visual.Material();
  if (!material || material->ScriptName().empty()) return out;
  const sdf::ElementPtr element = material->Element();
  const std::string name = material->ScriptName();
  const bool explicit_diffuse = element && element->HasElement("diffuse");
  if (gazeboMaterialColour(name) && !explicit_diffuse) return out;  // a stock material

  const std::vector<std::string> resource_paths = gazeboResourcePaths();
  const std::string defined_in = element && !element->FilePath().empty() ? element->FilePath()
                                                                         : source;
  std::error_code ec;
  const std::string base_dir =
      fs::is_regular_file(defined_in, ec) ? fs::path(defined_in).parent_path().string() : "";
  std::vector<std::string> uri_paths;
  for (const std::string& uri : scriptUris(*material)) {
    const std::string path = resolveScriptUri(uri, base_dir, resolver, resource_paths);
    if (!path.empty()) uri_paths.push_back(path);
  }
  std::vector<std::string> lookup_warnings;
  const auto found = findScriptMaterial(name, uri_paths, resource_paths, &lookup_warnings);
  for (const std::string& w : lookup_warnings) warnings->push_back(where + ": " + w);
  if (!found) {
    if (!gazeboMaterialColour(name)) {
      warnings->push_back(where + ": material script '" + name +
                          "' is not one of Gazebo's stock materials nor in any script of its "
                          "<uri>s or GAZEBO_RESOURCE_PATH: drawn grey");
    }
    return out;
  }
  if (!explicit_diffuse) {
    const OgreMaterial& m = found->material;
    out.rgba = m.diffuse ? *m.diffuse : m.ambient ? *m.ambient : Eigen::Vector4f::Ones();
  }
  if (found->material.texture_unit && !found->texture_path.empty()) out.texture = textureOf(*found);
  return out;
}

}  // namespace bullet_sim
