// The decoder module (libbullet_sim_image_file.so): image files through OpenCV.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "render/image_file.h"

extern "C" bool bullet_sim_decode_rgb_image(const char* path, bullet_sim::RgbImage* image) {
  const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) return false;
  image->width = bgr.cols;
  image->height = bgr.rows;
  image->bytes.resize(bgr.total() * 3);
  // Converted straight into the image's bytes: a Mat of the right size and type is written
  // in place, its rows without padding.
  cv::Mat rgb(bgr.rows, bgr.cols, CV_8UC3, image->bytes.data());
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return true;
}
