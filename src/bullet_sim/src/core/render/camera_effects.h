#ifndef BULLET_SIM_CORE_CAMERA_EFFECTS_H
#define BULLET_SIM_CORE_CAMERA_EFFECTS_H

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// Where each pixel of a distorted image takes its colour from in the ideal (pinhole) image:
/// Brown's model (k1 k2 k3 radial, p1 p2 tangential) in pixel units around (cx, cy) with
/// focal length f, as OpenCV's undistort() reads it: a point at normalised (x, y) =
/// ((u - cx) / f, (v - cy) / f) of the ideal image lands at cx + f x_d, cy + f y_d with
/// x_d = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y + p2 (r^2 + 2 x^2) and
/// y_d = y (1 + ...) + p1 (r^2 + 2 y^2) + 2 p2 x y. Pixel coordinates are OpenCV's (the
/// centre of pixel (i, j) at (i, j)). The map inverts the model per pixel by fixed-point
/// iteration; a pixel whose source lies outside the ideal image is black (Gazebo's
/// <borderCrop> false).
class DistortionMap {
 public:
  DistortionMap() = default;
  DistortionMap(const DistortionSpec& d, int width, int height, double f_px, double cx,
                double cy);

  /// The ideal pixel position that distorts onto pixel (u, v).
  std::array<double, 2> sourceOf(double u, double v) const;
  /// `distorted` (resized) from `ideal`, both rgb8 of the map's size: bilinear samples.
  void apply(const std::vector<uint8_t>& ideal, std::vector<uint8_t>* distorted) const;
  bool empty() const { return width_ == 0; }

 private:
  DistortionSpec d_;
  int width_ = 0, height_ = 0;
  double f_ = 1, cx_ = 0, cy_ = 0;
  std::vector<float> source_;  ///< per pixel: source u, v (u < 0 for none)
};

/// The distortion centre of a camera in OpenCV pixel coordinates: its camera_info's
/// principal point (cx, cy) shifted by <center> - 0.5 of the image size.
std::array<double, 2> distortionCentre(const CameraSpec& camera, double cx, double cy);

/// Writes an rgb8 frame into `out` in `encoding` (rgb8, bgr8, mono8, rgb16, mono16; 16-bit
/// values little-endian), adding gaussian noise when `noise` is set: per pixel one sample of
/// N(mean, stddev) from `rng`, added to each channel in [0, 1] and clamped there, then
/// quantised to the encoding's depth (Gazebo's image noise). Returns the step in bytes.
int encodeFrame(const std::vector<uint8_t>& rgb, int width, const std::string& encoding,
                const ImageNoiseSpec* noise, std::mt19937_64* rng, std::vector<uint8_t>* out);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_CAMERA_EFFECTS_H
