/// @file image_io.h
/// @brief Writes rendered images to disk for debugging and documentation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sim_render {

/// Writes a binary PPM (P6) of a row-major rgb8 image. Throws std::runtime_error naming the
/// path when the file cannot be written, std::invalid_argument when the buffer size does not
/// match width * height * 3.
void writePpm(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb8);

}  // namespace sim_render
