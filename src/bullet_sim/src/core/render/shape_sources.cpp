#include "render/shape_sources.h"

#include <algorithm>

#include "render/image_file.h"

namespace bullet_sim {

const std::vector<std::shared_ptr<const sim_render::Mesh>>& MeshTriangles::of(
    const std::shared_ptr<const TriangleMesh>& mesh) {
  auto [it, inserted] = parts_.try_emplace(mesh);
  if (inserted) {
    for (const MeshPart& part : mesh->parts) {
      auto triangles = std::make_shared<sim_render::Mesh>();
      triangles->vertices = part.vertices;
      triangles->triangles = part.triangles;
      triangles->uvs = part.uvs;
      it->second.push_back(std::move(triangles));
    }
  }
  return it->second;
}

std::shared_ptr<const sim_render::Texture> TextureImages::load(const std::string& path) {
  if (path.empty()) return nullptr;
  auto [it, inserted] = images_.try_emplace(path);
  if (!inserted) return it->second;
  RgbImage image;
  std::string error;
  if (!readRgbImage(path, &image, &error)) {
    warnings_->push_back("texture " + path + ": " + error + ": drawn in its colour");
    return nullptr;
  }
  it->second = std::make_shared<const sim_render::Texture>(image.width, image.height,
                                                           std::move(image.bytes));
  return it->second;
}

std::vector<sim_render::ShapeSpec> shapesOf(const Geometry& geometry,
                                            const std::shared_ptr<const TriangleMesh>& mesh,
                                            const Eigen::Vector4f& rgba, const TextureRef& texture,
                                            ShapeSources* sources) {
  if (geometry.kind != Geometry::Mesh) {
    sim_render::ShapeSpec shape(geometry, rgba);
    shape.texture = sources->textures.load(texture.path);
    shape.uv_transform.scale = texture.uv_scale;
    shape.uv_transform.offset = texture.uv_offset;
    return {shape};
  }
  std::vector<sim_render::ShapeSpec> shapes;
  if (!mesh) return shapes;
  const auto& parts = sources->triangles.of(mesh);
  for (size_t i = 0; i < parts.size(); ++i) {
    const MeshPart& file_part = mesh->parts[i];
    sim_render::ShapeSpec part(geometry, file_part.rgba.value_or(rgba));
    part.triangles = parts[i];
    if (!file_part.missing_texture.empty() &&
        sources->missing_reported.insert(mesh->path + file_part.missing_texture).second) {
      sources->textures.warn(mesh->path + ": texture '" + file_part.missing_texture +
                             "' not found beside the mesh or in ../materials/textures: "
                             "drawn in its colour");
    }
    if (!file_part.texture_path.empty()) {
      part.texture = sources->textures.load(file_part.texture_path);
      if (part.texture) part.rgba = Eigen::Vector4f::Ones();
    }
    shapes.push_back(std::move(part));
  }
  return shapes;
}

}  // namespace bullet_sim
