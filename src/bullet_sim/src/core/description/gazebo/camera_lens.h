#ifndef BULLET_SIM_CORE_CAMERA_LENS_H
#define BULLET_SIM_CORE_CAMERA_LENS_H

#include <string>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// The mapping of a wide-angle lens as Gazebo's WideAngleCamera models it: a ray at angle
/// theta from the optical axis lands at image radius r = c1 * f * fun(theta / c2 + c3), in
/// units of the image's half width, keeping its azimuth. Named types are presets of
/// (c1, c2, fun) with c3 = 0 and f = 1: gnomonical (1, 1, tan), stereographic (2, 2, tan),
/// equidistant (1, 1, id), equisolid_angle (2, 2, sin), orthographic (1, 1, sin); "custom"
/// takes the spec's values. With scale_to_hfov, f is chosen so that r = 1 (the image's
/// left and right edges) at theta = hfov / 2.
class CameraLens {
 public:
  enum class Fun { Sin, Tan, Id };

  /// @throws std::invalid_argument naming the lens element and its value (an unknown type or
  /// fun, c1, c2 or f zero or not finite, a cutoff outside (0, pi], an hfov outside
  /// (0, 2 pi] or one the mapping cannot reach with scale_to_hfov).
  CameraLens(const LensSpec& spec, double horizontal_fov_rad);

  /// Image radius (half widths) of a ray at `theta_rad` from the optical axis.
  double radius(double theta_rad) const;
  /// Angle from the optical axis of the rays landing at image radius `r`; NaN where none do
  /// (sin's inverse beyond 1).
  double angle(double r) const;
  double f() const { return f_; }
  double cutoffRad() const { return cutoff_rad_; }
  /// Focal length in pixels of the pinhole that matches the lens near the optical axis:
  /// (width / 2) * dr/dtheta at theta = 0.
  double paraxialFocalPx(int width) const;

 private:
  /// The custom function's c1, c2, c3, f and fun, checked.
  void useCustomFunction(const LensSpec& spec);
  /// The c1, c2 and fun of a named lens type.
  void usePreset(const std::string& type);
  /// c1 * fun(hfov / 2 / c2 + c3), the unscaled radius of the image's side edges.
  /// @throws std::invalid_argument when the mapping does not reach that far one to one.
  double edgeRadius(double horizontal_fov_rad, const std::string& type) const;
  double apply(double x) const;
  double slope(double x) const;  ///< derivative of fun at x

  double c1_ = 1, c2_ = 1, c3_ = 0, f_ = 1, cutoff_rad_ = 0;
  Fun fun_ = Fun::Tan;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_CAMERA_LENS_H
