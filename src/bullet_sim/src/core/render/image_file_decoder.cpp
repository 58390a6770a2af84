// The decoder module (libbullet_sim_image_file.so): image files through OpenCV.
#include <algorithm>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "render/image_file.h"

extern "C" bool bullet_sim_decode_rgb_image(const char* path, bullet_sim::RgbImage* image) {
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) return false;
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  const size_t row_bytes = static_cast<size_t>(rgb.cols) * 3;
  image->width = rgb.cols;
  image->height = rgb.rows;
  image->bytes.resize(row_bytes * rgb.rows);
  for (int row = 0; row < rgb.rows; ++row) {
    std::copy(rgb.ptr<uint8_t>(row), rgb.ptr<uint8_t>(row) + row_bytes,
              image->bytes.begin() + static_cast<ptrdiff_t>(row * row_bytes));
  }
  return true;
}
