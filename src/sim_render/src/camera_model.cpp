#include "sim_render/camera_model.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sim_render {
namespace {

template <typename T>
[[noreturn]] void reject(const char* field, T value, const char* rule) {
  std::ostringstream msg;
  msg << "sim_render::CameraModel: " << field << " = " << value << " is invalid (" << rule << ")";
  throw std::invalid_argument(msg.str());
}

}  // namespace

void CameraModel::validate() const {
  constexpr int kMaxSize = 16384;
  if (width <= 0 || width > kMaxSize) reject("width", width, "must be in 1..16384");
  if (height <= 0 || height > kMaxSize) reject("height", height, "must be in 1..16384");
  if (!(horizontal_fov_rad > 0.0 && horizontal_fov_rad < M_PI)) {
    reject("horizontal_fov_rad", horizontal_fov_rad, "must be in (0, pi)");
  }
  if (!(std::isfinite(clip_near_m) && clip_near_m > 0.0)) reject("clip_near_m", clip_near_m, "must be > 0");
  if (!(std::isfinite(clip_far_m) && clip_far_m > clip_near_m)) {
    reject("clip_far_m", clip_far_m, "must be finite and > clip_near_m");
  }
}

double CameraModel::fx() const { return 0.5 * width / std::tan(0.5 * horizontal_fov_rad); }

std::array<double, 9> CameraModel::K() const {
  return {fx(), 0.0, cx(), 0.0, fy(), cy(), 0.0, 0.0, 1.0};
}

std::array<double, 12> CameraModel::P() const {
  return {fx(), 0.0, cx(), 0.0, 0.0, fy(), cy(), 0.0, 0.0, 0.0, 1.0, 0.0};
}

bool CameraModel::project(const Eigen::Vector3d& p_camera, Eigen::Vector2d* uv) const {
  if (!(p_camera.x() > 0.0)) return false;
  *uv = Eigen::Vector2d(cx() - fx() * p_camera.y() / p_camera.x(), cy() - fy() * p_camera.z() / p_camera.x());
  return true;
}

}  // namespace sim_render
