#include "render/camera_effects.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bullet_sim {
namespace {

/// Fixed-point steps that invert the distortion; Brown's model with |k| ~ 0.1 converges to
/// well below a thousandth of a pixel in a handful.
constexpr int kInverseIterations = 20;

/// The distorted normalised position of the ideal one (x, y).
std::array<double, 2> distort(const DistortionSpec& d, double x, double y) {
  const double r2 = x * x + y * y;
  const double radial = 1 + d.k1 * r2 + d.k2 * r2 * r2 + d.k3 * r2 * r2 * r2;
  return {x * radial + 2 * d.p1 * x * y + d.p2 * (r2 + 2 * x * x),
          y * radial + d.p1 * (r2 + 2 * y * y) + 2 * d.p2 * x * y};
}

uint8_t sampleChannel(const std::vector<uint8_t>& rgb, int width, int x0, int y0, double fx,
                      double fy, int c) {
  const auto at = [&](int x, int y) { return double(rgb[3 * (size_t(y) * width + x) + c]); };
  const double top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
  const double bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
  return static_cast<uint8_t>(std::lround(top * (1 - fy) + bottom * fy));
}

double luminance(const uint8_t* p) { return (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0; }

}  // namespace

DistortionMap::DistortionMap(const DistortionSpec& d, int width, int height, double f_px,
                             double cx, double cy)
    : d_(d), width_(width), height_(height), f_(f_px), cx_(cx), cy_(cy) {
  source_.resize(2 * size_t(width) * height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const std::array<double, 2> s = sourceOf(u, v);
      const bool inside = s[0] >= 0 && s[1] >= 0 && s[0] <= width - 1 && s[1] <= height - 1;
      float* out = &source_[2 * (size_t(v) * width + u)];
      out[0] = inside ? static_cast<float>(s[0]) : -1.0f;
      out[1] = inside ? static_cast<float>(s[1]) : -1.0f;
    }
  }
}

std::array<double, 2> DistortionMap::sourceOf(double u, double v) const {
  const double xd = (u - cx_) / f_, yd = (v - cy_) / f_;
  double x = xd, y = yd;
  for (int i = 0; i < kInverseIterations; ++i) {
    const std::array<double, 2> p = distort(d_, x, y);
    x += xd - p[0];
    y += yd - p[1];
  }
  return {cx_ + f_ * x, cy_ + f_ * y};
}

void DistortionMap::apply(const std::vector<uint8_t>& ideal, std::vector<uint8_t>* distorted) const {
  distorted->assign(3 * size_t(width_) * height_, 0);
  for (size_t i = 0; i < size_t(width_) * height_; ++i) {
    const float su = source_[2 * i], sv = source_[2 * i + 1];
    if (su < 0) continue;
    const int x0 = std::min(static_cast<int>(su), width_ - 2);
    const int y0 = std::min(static_cast<int>(sv), height_ - 2);
    for (int c = 0; c < 3; ++c) {
      (*distorted)[3 * i + c] = sampleChannel(ideal, width_, x0, y0, su - x0, sv - y0, c);
    }
  }
}

std::array<double, 2> distortionCentre(const CameraSpec& camera, double cx, double cy) {
  if (!camera.distortion) return {cx, cy};
  return {cx + (camera.distortion->center_x - 0.5) * camera.width,
          cy + (camera.distortion->center_y - 0.5) * camera.height};
}

int encodeFrame(const std::vector<uint8_t>& rgb, int width, const std::string& encoding,
                const ImageNoiseSpec* noise, std::mt19937_64* rng, std::vector<uint8_t>* out) {
  const size_t pixels = rgb.size() / 3;
  const bool mono = encoding == "mono8" || encoding == "mono16";
  const bool wide = encoding == "rgb16" || encoding == "mono16";
  const bool bgr = encoding == "bgr8";
  if (!mono && !wide && !bgr && encoding != "rgb8") {
    throw std::invalid_argument("encoding '" + encoding + "' is not rgb8, bgr8, mono8, rgb16 "
                                "or mono16");
  }
  const int channels = mono ? 1 : 3;
  const int bytes = wide ? 2 : 1;
  out->resize(pixels * channels * bytes);
  std::normal_distribution<double> gauss(noise ? noise->mean : 0.0, noise ? noise->stddev : 1.0);
  const double full = wide ? 65535.0 : 255.0;
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t* p = &rgb[3 * i];
    const double n = noise ? gauss(*rng) : 0.0;
    double value[3];
    if (mono) {
      value[0] = luminance(p);
    } else {
      for (int c = 0; c < 3; ++c) value[c] = p[bgr ? 2 - c : c] / 255.0;
    }
    for (int c = 0; c < channels; ++c) {
      const long q = std::lround(std::clamp(value[c] + n, 0.0, 1.0) * full);
      uint8_t* dst = &(*out)[(i * channels + c) * bytes];
      dst[0] = static_cast<uint8_t>(q & 0xff);
      if (wide) dst[1] = static_cast<uint8_t>(q >> 8);
    }
  }
  return width * channels * bytes;
}

}  // namespace bullet_sim
