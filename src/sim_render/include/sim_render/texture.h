/// @file texture.h
/// @brief An RGB image that surfaces are painted with, and its mipmaps.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace sim_render {

/// One level of a texture: width x height texels, rgb8, row-major, row 0 at v = 0.
struct TextureLevel {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb8;
};

/// An image mapped onto surfaces by texture coordinates (u, v): u = 0..1 from the left
/// column to the right, v = 0..1 from the top row to the bottom (OGRE's and COLLADA-after-
/// flip convention). Coordinates outside 0..1 wrap (OGRE's default address mode).
///
/// Sampling is nearest-texel from the mipmap level whose texels best match the pixel's
/// footprint (each level halves the one before it, 2x2 box-filtered, down to 1x1), so that
/// a far floor shows its texture's average rather than aliasing. The level is chosen once
/// per drawn span (see Renderer), not per pixel.
class Texture {
 public:
  /// Builds the texture and its mipmaps from `rgb8` (width * height * 3 bytes).
  /// Throws std::invalid_argument naming the value when a size is not positive or the
  /// data does not hold width * height * 3 bytes.
  Texture(int width, int height, std::vector<std::uint8_t> rgb8);

  int width() const { return levels_.front().width; }
  int height() const { return levels_.front().height; }
  const std::vector<TextureLevel>& levels() const { return levels_; }
  /// Mean colour of the whole image, 0..1 (the last mipmap level), for surfaces that are
  /// drawn without texture coordinates.
  Eigen::Vector3f meanColour() const;

  /// The texel of level `level` under (u, v), wrapped; for tests and tools.
  const std::uint8_t* texel(double u, double v, int level = 0) const;

 private:
  std::vector<TextureLevel> levels_;
};

/// Per-axis affine map applied to texture coordinates: uv' = scale * uv + offset
/// (OGRE texture_unit `scale` and `scroll` come down to one of these).
struct UvTransform {
  Eigen::Vector2f scale{1.0f, 1.0f};
  Eigen::Vector2f offset{0.0f, 0.0f};
  Eigen::Vector2f apply(const Eigen::Vector2f& uv) const {
    return scale.cwiseProduct(uv) + offset;
  }
};

}  // namespace sim_render
