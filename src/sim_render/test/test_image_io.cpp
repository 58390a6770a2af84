#include "sim_render/image_io.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

TEST(ImageIo, WritesBinaryPpm) {
  const std::string path = testing::TempDir() + "sim_render_test_image.ppm";
  const std::vector<std::uint8_t> rgb = {255, 0, 0, 0, 128, 255};
  sim_render::writePpm(path, 2, 1, rgb);
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes, std::string("P6\n2 1\n255\n") + std::string(rgb.begin(), rgb.end()));
  std::remove(path.c_str());
}

TEST(ImageIo, RejectsWrongSizeAndUnwritablePath) {
  try {
    sim_render::writePpm("/tmp/never_written.ppm", 2, 2, std::vector<std::uint8_t>(5));
    FAIL() << "a 5-byte buffer was accepted as 2x2";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("5 bytes"), std::string::npos) << e.what();
  }
  try {
    sim_render::writePpm("/nonexistent_dir/x.ppm", 1, 1, std::vector<std::uint8_t>(3));
    FAIL() << "writing into a missing directory succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_dir/x.ppm"), std::string::npos) << e.what();
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
