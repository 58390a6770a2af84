#ifndef BULLET_SIM_CORE_OGRE_MATERIAL_H
#define BULLET_SIM_CORE_OGRE_MATERIAL_H

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace bullet_sim {

/// The first texture unit of a material's pass: the image file OGRE looks up by name in its
/// resource locations, and its texture-coordinate scale and scroll.
struct OgreTextureUnit {
  std::string texture;
  Eigen::Vector2d scale{1, 1};
  Eigen::Vector2d scroll{0, 0};
};

/// What the renderer uses of an OGRE material: its first technique's first pass.
struct OgreMaterial {
  std::string name;
  std::string script_path;  ///< the .material file defining it
  /// rgba; absent when the pass does not set it or sets `vertexcolour`.
  std::optional<Eigen::Vector4f> ambient, diffuse;
  /// The pass's first texture_unit, when it names a `texture`.
  std::optional<OgreTextureUnit> texture_unit;
};

/// The materials of OGRE material script `text` (read from `source_path`), in file order.
/// `material NAME [: PARENT] { technique { pass { ... } } }` blocks are read; `ambient` and
/// `diffuse` (3 or 4 numbers, alpha 1 by default) and the first texture_unit's `texture`,
/// `scale` and `scroll` are kept, everything else (other techniques and passes, programs,
/// `import` lines, `abstract` blocks, unknown attributes) is skipped. A child starts from
/// its parent's values when the parent is defined earlier in the same text. Syntax errors
/// (see parseOgreScript) and malformed values throw LoadError naming the file, the line and
/// the text.
std::vector<OgreMaterial> parseOgreMaterials(const std::string& text,
                                             const std::string& source_path);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_OGRE_MATERIAL_H
