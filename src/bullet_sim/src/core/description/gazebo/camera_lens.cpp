#include "description/gazebo/camera_lens.h"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace bullet_sim {
namespace {

struct Preset {
  double c1, c2;
  CameraLens::Fun fun;
};

const std::map<std::string, Preset>& presets() {
  static const std::map<std::string, Preset> table = {
      {"gnomonical", {1, 1, CameraLens::Fun::Tan}},
      {"stereographic", {2, 2, CameraLens::Fun::Tan}},
      {"equidistant", {1, 1, CameraLens::Fun::Id}},
      {"equisolid_angle", {2, 2, CameraLens::Fun::Sin}},
      {"orthographic", {1, 1, CameraLens::Fun::Sin}}};
  return table;
}

CameraLens::Fun funOf(const std::string& name) {
  if (name == "sin") return CameraLens::Fun::Sin;
  if (name == "tan") return CameraLens::Fun::Tan;
  if (name == "id") return CameraLens::Fun::Id;
  throw std::invalid_argument("<custom_function> <fun>: '" + name + "' is not sin, tan or id");
}

std::string number(double v) { return std::to_string(v); }

void requireNonZero(double v, const char* element) {
  if (!(std::isfinite(v) && v != 0)) {
    throw std::invalid_argument(std::string("<custom_function> <") + element + ">: '" +
                                number(v) + "' must be finite and not 0");
  }
}

}  // namespace

CameraLens::CameraLens(const LensSpec& spec, double horizontal_fov_rad) {
  if (spec.type == "custom") {
    useCustomFunction(spec);
  } else {
    usePreset(spec.type);
  }
  if (!(spec.cutoff_angle_rad > 0 && spec.cutoff_angle_rad <= M_PI)) {
    throw std::invalid_argument("<cutoff_angle>: '" + number(spec.cutoff_angle_rad) +
                                "' must be in (0, pi] radians");
  }
  cutoff_rad_ = spec.cutoff_angle_rad;
  if (!(horizontal_fov_rad > 0 && horizontal_fov_rad <= 2 * M_PI)) {
    throw std::invalid_argument("<horizontal_fov>: '" + number(horizontal_fov_rad) +
                                "' must be in (0, 2 pi] radians for a wide-angle camera");
  }
  if (spec.scale_to_hfov) f_ = 1.0 / edgeRadius(horizontal_fov_rad, spec.type);
}

void CameraLens::useCustomFunction(const LensSpec& spec) {
  requireNonZero(spec.c1, "c1");
  requireNonZero(spec.c2, "c2");
  requireNonZero(spec.f, "f");
  if (!std::isfinite(spec.c3)) {
    throw std::invalid_argument("<custom_function> <c3>: '" + number(spec.c3) +
                                "' is not finite");
  }
  c1_ = spec.c1, c2_ = spec.c2, c3_ = spec.c3, f_ = spec.f;
  fun_ = funOf(spec.fun);
}

void CameraLens::usePreset(const std::string& type) {
  const auto it = presets().find(type);
  if (it == presets().end()) {
    throw std::invalid_argument("<type>: '" + type +
                                "' is not gnomonical, stereographic, equidistant, "
                                "equisolid_angle, orthographic or custom");
  }
  c1_ = it->second.c1, c2_ = it->second.c2, fun_ = it->second.fun;
}

double CameraLens::edgeRadius(double horizontal_fov_rad, const std::string& type) const {
  const double x_edge = 0.5 * horizontal_fov_rad / c2_ + c3_;
  const double edge = c1_ * apply(x_edge);
  // sin and tan map angles one to one only up to pi / 2 (tan's pole, sin's peak).
  const bool one_to_one = fun_ == Fun::Id || (fun_ == Fun::Sin && std::abs(x_edge) <= M_PI_2) ||
                          (fun_ == Fun::Tan && std::abs(x_edge) < M_PI_2);
  if (!(one_to_one && std::isfinite(edge) && edge > 0)) {
    throw std::invalid_argument("<horizontal_fov>: '" + number(horizontal_fov_rad) +
                                "' is beyond what lens '" + type + "' maps (scale_to_hfov)");
  }
  return edge;
}

double CameraLens::apply(double x) const {
  switch (fun_) {
    case Fun::Sin: return std::sin(x);
    case Fun::Tan: return std::tan(x);
    case Fun::Id: return x;
  }
  return x;
}

double CameraLens::slope(double x) const {
  switch (fun_) {
    case Fun::Sin: return std::cos(x);
    case Fun::Tan: return 1.0 / (std::cos(x) * std::cos(x));
    case Fun::Id: return 1.0;
  }
  return 1.0;
}

double CameraLens::radius(double theta_rad) const {
  return c1_ * f_ * apply(theta_rad / c2_ + c3_);
}

double CameraLens::angle(double r) const {
  const double param = r / (c1_ * f_);
  double inverse = param;
  if (fun_ == Fun::Sin) {
    if (std::abs(param) > 1) return std::numeric_limits<double>::quiet_NaN();
    inverse = std::asin(param);
  } else if (fun_ == Fun::Tan) {
    inverse = std::atan(param);
  }
  return c2_ * (inverse - c3_);
}

double CameraLens::paraxialFocalPx(int width) const {
  return 0.5 * width * c1_ * f_ * slope(c3_) / c2_;
}

}  // namespace bullet_sim
