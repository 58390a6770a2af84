#include "bullet_sim/render/textured_mesh.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

#include <sim_render/tessellation.h>

namespace bullet_sim {
namespace {

namespace fs = std::filesystem;

/// The OBJ text of a tessellated shape: positions, coordinates with OBJ's v counted up from
/// the image's bottom row, one face per triangle.
std::string objText(const sim_render::Mesh& mesh, const std::string& mtl) {
  std::ostringstream out;
  out << std::setprecision(9) << "mtllib " << mtl << "\nusemtl painted\n";
  for (const Eigen::Vector3d& v : mesh.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const Eigen::Vector2f& uv : mesh.uvs) out << "vt " << uv.x() << " " << 1.0f - uv.y() << "\n";
  for (const auto& t : mesh.triangles) {
    out << "f";
    for (uint32_t i : t) out << " " << i + 1 << "/" << i + 1;
    out << "\n";
  }
  return out.str();
}

}  // namespace

std::string writeTexturedMesh(const Geometry& geometry, const TextureRef& texture,
                              const std::string& folder, std::string* reason) {
  sim_render::ShapeSpec spec(geometry, Eigen::Vector4f::Ones());
  // Any image turns the coordinates on; the file names the real one.
  spec.texture = std::make_shared<const sim_render::Texture>(1, 1, std::vector<uint8_t>(3, 0));
  spec.uv_transform.scale = texture.uv_scale;
  spec.uv_transform.offset = texture.uv_offset;
  sim_render::Mesh mesh;
  try {
    mesh = sim_render::tessellate(spec);
  } catch (const std::invalid_argument& e) {
    *reason = e.what();
    return "";
  }
  if (mesh.uvs.size() != mesh.vertices.size()) {
    *reason = std::string("a ") + kindName(geometry.kind) + " has no texture coordinates";
    return "";
  }
  const fs::path image(texture.path);
  const std::string obj = objText(mesh, "MTL");
  std::ostringstream key;
  key << obj << texture.path;
  const std::string stem = "textured_" + std::to_string(std::hash<std::string>()(key.str()));
  const fs::path dir(folder), obj_path = dir / (stem + ".obj");
  std::error_code ec;
  if (fs::exists(obj_path, ec)) return obj_path.string();
  fs::create_directories(dir, ec);
  // RViz looks textures up beside the mesh, by the name the MTL gives.
  const fs::path image_link = dir / (stem + image.extension().string());
  fs::remove(image_link, ec);
  fs::create_symlink(fs::absolute(image, ec), image_link, ec);
  std::ofstream(dir / (stem + ".mtl")) << "newmtl painted\nKa 1 1 1\nKd 1 1 1\nmap_Kd "
                                       << image_link.filename().string() << "\n";
  const fs::path partial = dir / (stem + ".obj.part");
  {
    std::ofstream out(partial);
    out << objText(mesh, stem + ".mtl");
    if (!out) {
      *reason = "cannot write " + partial.string();
      return "";
    }
  }
  fs::rename(partial, obj_path, ec);  // whole or not at all, for a viewer reading it
  if (ec) {
    *reason = "cannot write " + obj_path.string() + ": " + ec.message();
    return "";
  }
  return obj_path.string();
}

}  // namespace bullet_sim
