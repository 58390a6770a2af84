#include "sim_render/texture.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sim_render {
namespace {

/// The next mipmap level: each texel the mean of the (up to) 2x2 texels it covers.
TextureLevel halve(const TextureLevel& in) {
  TextureLevel out;
  out.width = std::max(1, in.width / 2);
  out.height = std::max(1, in.height / 2);
  out.rgb8.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  for (int y = 0; y < out.height; ++y) {
    const int y0 = std::min(2 * y, in.height - 1), y1 = std::min(2 * y + 1, in.height - 1);
    for (int x = 0; x < out.width; ++x) {
      const int x0 = std::min(2 * x, in.width - 1), x1 = std::min(2 * x + 1, in.width - 1);
      for (int c = 0; c < 3; ++c) {
        const auto at = [&](int xx, int yy) {
          return in.rgb8[(static_cast<std::size_t>(yy) * in.width + xx) * 3 + c];
        };
        const int sum = at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1);
        out.rgb8[(static_cast<std::size_t>(y) * out.width + x) * 3 + c] =
            static_cast<std::uint8_t>((sum + 2) / 4);
      }
    }
  }
  return out;
}

int wrapped(double coordinate, int size) {
  const double fraction = coordinate - std::floor(coordinate);
  return std::min(size - 1, static_cast<int>(fraction * size));
}

}  // namespace

Texture::Texture(int width, int height, std::vector<std::uint8_t> rgb8) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("texture size must be positive, got " + std::to_string(width) +
                                " x " + std::to_string(height));
  }
  const std::size_t expected = static_cast<std::size_t>(width) * height * 3;
  if (rgb8.size() != expected) {
    throw std::invalid_argument("texture of " + std::to_string(width) + " x " +
                                std::to_string(height) + " needs " + std::to_string(expected) +
                                " bytes of rgb8, got " + std::to_string(rgb8.size()));
  }
  levels_.push_back(TextureLevel{width, height, std::move(rgb8)});
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    levels_.push_back(halve(levels_.back()));
  }
}

Eigen::Vector3f Texture::meanColour() const {
  const std::uint8_t* t = levels_.back().rgb8.data();
  return Eigen::Vector3f(t[0], t[1], t[2]) / 255.0f;
}

const std::uint8_t* Texture::texel(double u, double v, int level) const {
  const TextureLevel& l = levels_.at(static_cast<std::size_t>(level));
  const int x = wrapped(u, l.width), y = wrapped(v, l.height);
  return &l.rgb8[(static_cast<std::size_t>(y) * l.width + x) * 3];
}

}  // namespace sim_render
