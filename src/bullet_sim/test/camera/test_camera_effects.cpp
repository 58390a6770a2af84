// What the camera does to a rendered frame: Brown distortion consistent with the
// camera_info it publishes (OpenCV's undistort() with that K and D gives the ideal image
// back, as gazebo_ros_pkgs' distortion tests check), seeded gaussian noise per pixel, and
// the 16-bit encodings.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "bullet_sim/render/camera_renderer.h"
#include "render/camera_effects.h"

using namespace bullet_sim;

namespace {

constexpr int kSize = 200;

/// An ideal image: a smooth pattern (period 40 pixels), rgb8, so that resampling it twice
/// costs little next to a distortion that is off.
std::vector<uint8_t> pattern() {
  std::vector<uint8_t> rgb(3 * kSize * kSize);
  for (int v = 0; v < kSize; ++v) {
    for (int u = 0; u < kSize; ++u) {
      const double value = 127 + 100 * std::sin(2 * M_PI * u / 40) * std::cos(2 * M_PI * v / 40);
      for (int c = 0; c < 3; ++c) rgb[3 * (v * kSize + u) + c] = static_cast<uint8_t>(value);
    }
  }
  return rgb;
}

/// Sum of |a - b| over the centre of two rgb8 images (a 40-pixel border left out).
long centreDifference(const cv::Mat& a, const cv::Mat& b) {
  const cv::Rect centre(40, 40, kSize - 80, kSize - 80);
  return static_cast<long>(cv::norm(a(centre), b(centre), cv::NORM_L1));
}

}  // namespace

TEST(CameraEffects, TheDistortionMapInvertsBrownsModel) {
  // k1 = -0.1, f = 1000, centre (500, 500): the ideal point (800, 500) has x = 0.3,
  // r^2 = 0.09, radial factor 1 - 0.009 = 0.991, so it lands at 500 + 1000 * 0.2973.
  DistortionSpec d;
  d.k1 = -0.1;
  const DistortionMap map(d, 1000, 1000, 1000, 500, 500);
  const std::array<double, 2> s = map.sourceOf(797.3, 500);
  EXPECT_NEAR(s[0], 800, 1e-6);
  EXPECT_NEAR(s[1], 500, 1e-6);
  // tangential: p1 = 0.01 moves (x, y) = (0.1, 0.2) by (2 p1 x y, p1 (r^2 + 2 y^2)) =
  // (0.0004, 0.0013) in normalised units
  DistortionSpec t;
  t.p1 = 0.01;
  const DistortionMap tangential(t, 1000, 1000, 1000, 500, 500);
  const std::array<double, 2> st = tangential.sourceOf(600.4, 701.3);
  EXPECT_NEAR(st[0], 600, 1e-6);
  EXPECT_NEAR(st[1], 700, 1e-6);
}

TEST(CameraEffects, OpenCvUndistortsTheImageBackWithTheCoefficientsCameraInfoPublishes) {
  for (const double k : {-0.1, 0.1}) {  // barrel, pincushion
    SCOPED_TRACE(k);
    DistortionSpec d;
    d.k1 = d.k2 = d.k3 = k;
    const double f = 100, cx = 100, cy = 100;
    const DistortionMap map(d, kSize, kSize, f, cx, cy);
    const std::vector<uint8_t> ideal = pattern();
    std::vector<uint8_t> distorted;
    map.apply(ideal, &distorted);
    const cv::Mat ideal_mat(kSize, kSize, CV_8UC3, const_cast<uint8_t*>(ideal.data()));
    const cv::Mat distorted_mat(kSize, kSize, CV_8UC3, distorted.data());
    const cv::Mat K = (cv::Mat_<double>(3, 3) << f, 0, cx, 0, f, cy, 0, 0, 1);
    cv::Mat D = (cv::Mat_<double>(5, 1) << k, k, 0, 0, k);
    cv::Mat fixed;
    cv::undistort(distorted_mat, fixed, K, D);
    const long best = centreDifference(fixed, ideal_mat);
    EXPECT_GT(centreDifference(distorted_mat, ideal_mat), 2 * best);
    for (int i = 0; i < 5; ++i) {  // each coefficient 0.05 off undistorts worse
      for (const double off : {-0.05, 0.05}) {
        D.at<double>(i) += off;
        cv::undistort(distorted_mat, fixed, K, D);
        EXPECT_GT(centreDifference(fixed, ideal_mat), best) << "D[" << i << "] " << off
                                                             << " best " << best;
        D.at<double>(i) -= off;
      }
    }
  }
}

TEST(CameraEffects, SixteenBitEncodingsScaleTheChannelsToFullRange) {
  const std::vector<uint8_t> rgb{255, 128, 0};
  std::mt19937_64 rng(1);
  std::vector<uint8_t> out;
  EXPECT_EQ(encodeFrame(rgb, 1, "rgb16", nullptr, &rng, &out), 6);
  // 255 -> 65535, 128 -> 128 * 257 = 32896, little-endian
  EXPECT_EQ(out, (std::vector<uint8_t>{0xff, 0xff, 0x80, 0x80, 0x00, 0x00}));
  EXPECT_EQ(encodeFrame(rgb, 1, "mono16", nullptr, &rng, &out), 2);
  // luminance 0.299 * 1 + 0.587 * 128 / 255 = 0.593651 -> 38905
  const int mono = out[0] | (out[1] << 8);
  EXPECT_EQ(mono, std::lround((0.299 + 0.587 * 128.0 / 255.0) * 65535));
  EXPECT_EQ(encodeFrame(rgb, 1, "bgr8", nullptr, &rng, &out), 3);
  EXPECT_EQ(out, (std::vector<uint8_t>{0, 128, 255}));
}

TEST(CameraEffects, GaussianNoiseIsOneSeededSamplePerPixelAddedToEachChannel) {
  const int n = 100000;
  const std::vector<uint8_t> grey(3 * n, 128);
  ImageNoiseSpec noise;
  noise.mean = 0.02;
  noise.stddev = 0.05;
  std::mt19937_64 rng(7);
  std::vector<uint8_t> out;
  encodeFrame(grey, n, "rgb16", &noise, &rng, &out);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const auto channel = [&](int c) { return out[6 * i + 2 * c] | (out[6 * i + 2 * c + 1] << 8); };
    ASSERT_EQ(channel(0), channel(1));
    ASSERT_EQ(channel(1), channel(2));
    const double e = channel(0) / 65535.0 - 128.0 / 255.0;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.02, 0.001);   // 4 standard errors (0.05 / sqrt(1e5) = 0.00016)
  EXPECT_NEAR(sd, 0.05, 0.001);
  std::mt19937_64 same(7), other(8);
  std::vector<uint8_t> again, different;
  encodeFrame(grey, n, "rgb16", &noise, &same, &again);
  encodeFrame(grey, n, "rgb16", &noise, &other, &different);
  EXPECT_EQ(out, again);
  EXPECT_NE(out, different);
}

TEST(CameraEffects, CameraInfoPublishesTheDistortionAndTheBaseline) {
  CameraSpec c;
  c.width = 640;
  c.height = 480;
  c.horizontal_fov_rad = 1.3962634;
  c.info_distortion = {-0.1, -0.2, 0.01, 0.02, -0.3};
  c.hack_baseline_m = 0.07;
  const CameraInfoData info = cameraInfo(c, 0);
  const double fx = 320 / std::tan(1.3962634 / 2);
  EXPECT_NEAR(info.K[0], fx, 1e-9);
  EXPECT_EQ(info.D, c.info_distortion);
  EXPECT_NEAR(info.P[3], -fx * 0.07, 1e-9);
}
