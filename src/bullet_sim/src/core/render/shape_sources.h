#ifndef BULLET_SIM_CORE_SHAPE_SOURCES_H
#define BULLET_SIM_CORE_SHAPE_SOURCES_H

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <sim_render/shape.h>
#include <sim_render/texture.h>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// The renderer's triangles of each part of a mesh file, made once per file.
class MeshTriangles {
 public:
  const std::vector<std::shared_ptr<const sim_render::Mesh>>& of(
      const std::shared_ptr<const TriangleMesh>& mesh);

 private:
  std::map<std::shared_ptr<const TriangleMesh>,
           std::vector<std::shared_ptr<const sim_render::Mesh>>> parts_;
};

/// Texture images, each file decoded once (render/image_file.h) and shared by every shape showing it.
class TextureImages {
 public:
  explicit TextureImages(std::vector<std::string>* warnings) : warnings_(warnings) {}

  /// The image in `path`, or null (with one warning naming the file) when it cannot be read.
  std::shared_ptr<const sim_render::Texture> load(const std::string& path);

  void warn(const std::string& message) { warnings_->push_back(message); }

 private:
  std::vector<std::string>* warnings_;
  std::map<std::string, std::shared_ptr<const sim_render::Texture>> images_;
};

/// What the renderer needs to draw shapes: mesh triangles and texture images, made once.
struct ShapeSources {
  MeshTriangles triangles;
  TextureImages textures;
  std::set<std::string> missing_reported;  ///< mesh files whose missing texture was named
};

/// The renderer's shapes of a geometry in colour `rgba` (with the material's `texture`, if
/// any): one for a primitive; for a mesh, whose triangles `mesh` holds, one per part, a
/// part without a colour of its own taking `rgba`, a part with a texture of its own showing
/// it unshaded by any colour. A mesh that could not be read (null) has none: the loader
/// already warned.
std::vector<sim_render::ShapeSpec> shapesOf(const Geometry& geometry,
                                            const std::shared_ptr<const TriangleMesh>& mesh,
                                            const Eigen::Vector4f& rgba, const TextureRef& texture,
                                            ShapeSources* sources);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SHAPE_SOURCES_H
