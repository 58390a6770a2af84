#include "sim_render/image_io.h"

#include <fstream>
#include <stdexcept>

namespace sim_render {

void writePpm(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb8) {
  if (width <= 0 || height <= 0 ||
      rgb8.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    throw std::invalid_argument("writePpm(" + path + "): buffer of " + std::to_string(rgb8.size()) +
                                " bytes does not hold a " + std::to_string(width) + "x" +
                                std::to_string(height) + " rgb8 image");
  }
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << width << " " << height << "\n255\n";
  out.write(reinterpret_cast<const char*>(rgb8.data()), static_cast<std::streamsize>(rgb8.size()));
  if (!out) throw std::runtime_error("writePpm: cannot write " + path);
}

}  // namespace sim_render
