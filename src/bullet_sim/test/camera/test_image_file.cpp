// Image files through the decoder module: the pixels of a file written here byte by byte,
// OpenCV's imgcodecs mapped only once the first image is read, and unreadable files named.
#include <gtest/gtest.h>
#include <link.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "render/image_file.h"

namespace {

using bullet_sim::readRgbImage;
using bullet_sim::RgbImage;

bool imgcodecsMapped() {
  bool found = false;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        if (info->dlpi_name && std::strstr(info->dlpi_name, "libopencv_imgcodecs")) {
          *static_cast<bool*>(data) = true;
        }
        return 0;
      },
      &found);
  return found;
}

std::string scratchFile(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("bullet_sim_image_file_" + std::to_string(getpid()) + "_" + name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

// One test, in order: the first read is what maps the decoder.
TEST(ImageFile, DecodesOnFirstUseAndNamesUnreadableFiles) {
  EXPECT_FALSE(imgcodecsMapped()) << "imgcodecs is mapped before any image was read";

  // A binary PPM, 3 wide and 2 high: red, green, blue / white, black, grey (128).
  const std::string pixels("\xff\x00\x00\x00\xff\x00\x00\x00\xff"
                           "\xff\xff\xff\x00\x00\x00\x80\x80\x80", 18);
  const std::string ppm = scratchFile("rgb.ppm", "P6\n3 2\n255\n" + pixels);
  RgbImage image;
  std::string error;
  ASSERT_TRUE(readRgbImage(ppm, &image, &error)) << error;
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(std::string(image.bytes.begin(), image.bytes.end()), pixels);
  EXPECT_TRUE(imgcodecsMapped());

  const std::string text = scratchFile("not_an_image.png", "no image here");
  RgbImage none;
  EXPECT_FALSE(readRgbImage(text, &none, &error));
  EXPECT_EQ(error, "cannot read the image");
  EXPECT_FALSE(readRgbImage(text + ".missing", &none, &error));
  std::filesystem::remove(ppm);
  std::filesystem::remove(text);
}

}  // namespace
