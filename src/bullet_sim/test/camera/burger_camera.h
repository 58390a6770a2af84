// The Burger's camera as the camera gtests see it (at the origin, yaw 0), and its pixels.
#pragma once

#include <cmath>
#include <cstddef>
#include <ostream>

#include <Eigen/Core>

#include "bullet_sim/render/camera_renderer.h"

namespace bullet_sim_test {

constexpr int kWidth = 640, kHeight = 480;
// base_footprint -> base_link 0.010 up, base_link -> camera_link (0.02, 0, 0.295); hfov 1.5707.
const Eigen::Vector3d kCamera(0.02, 0, 0.305);
const double kFocal = (kWidth / 2.0) / std::tan(1.5707 / 2.0);
// The world has no light of its own: default ambient 0.4, and the default light comes from
// above and behind +x, so faces turned towards -x get the ambient only.
constexpr double kAmbient = 0.4;

struct Rgb {
  int r, g, b;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};
inline std::ostream& operator<<(std::ostream& out, const Rgb& p) {
  return out << "(" << p.r << ", " << p.g << ", " << p.b << ")";
}

inline Rgb pixel(const bullet_sim::ImageData& image, int col, int row) {
  const size_t i = static_cast<size_t>(row) * image.step + 3 * static_cast<size_t>(col);
  return {image.data[i], image.data[i + 1], image.data[i + 2]};
}

}  // namespace bullet_sim_test
