#ifndef BULLET_SIM_CORE_RENDER_IMAGE_FILE_H
#define BULLET_SIM_CORE_RENDER_IMAGE_FILE_H

#include <cstdint>
#include <string>
#include <vector>

namespace bullet_sim {

/// An image as 8-bit RGB rows, top row first, no padding.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> bytes;
};

/// The decoder module's file name. OpenCV's imgcodecs decodes the files; it brings 128
/// shared libraries (GDAL and its formats), so it lives in a module of its own, loaded
/// with the first image: a simulation without textures never maps it.
constexpr const char* kImageFileModule = "libbullet_sim_image_file.so";

/// The module's one function: decodes the image file `path` (PNG, JPEG, or any format
/// OpenCV reads) into `image`; false when the file cannot be read as an image.
extern "C" bool bullet_sim_decode_rgb_image(const char* path, RgbImage* image);

/// Reads the image file `path` into `image` through the decoder module, loaded on the first
/// call from the folder of the library holding this function (else the loader's search
/// path). False with `*error` saying why: the file cannot be read as an image, or the
/// module cannot be loaded (its path and the loader's message).
bool readRgbImage(const std::string& path, RgbImage* image, std::string* error);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_RENDER_IMAGE_FILE_H
