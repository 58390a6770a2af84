#ifndef BULLET_SIM_DEPTH_CAMERA_H
#define BULLET_SIM_DEPTH_CAMERA_H

#include <cstdint>
#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/render/camera_renderer.h"

namespace bullet_sim {

/// A depth image, laid out as sensor_msgs/Image with encoding 32FC1: metres along the
/// optical axis (z of the optical frame), row-major, row 0 on top; NaN where nothing was
/// hit within the far clip distance or the depth is outside the plugin's cutoffs.
struct DepthImageData {
  double time_s = 0;
  std::string frame_id;
  int width = 0, height = 0;
  std::vector<float> depth_m;
};

/// A point cloud laid out as sensor_msgs/PointCloud2 with the fields Gazebo's depth plugins
/// give it: x, y, z float32 at bytes 0, 4 and 8 and rgb (float32 in name) at byte 16 of a
/// 32-byte point. Organised: one point per pixel, `height` rows of `width`. A point is in
/// the optical frame (x right, y down, z forward); NaN x, y, z where the depth is NaN, and
/// then is_dense is false. Byte 16..18 of a point are its pixel's bytes in the colour
/// image's order (rgb8: r g b, bgr8: b g r, mono8: the one byte thrice), byte 19 is 0.
struct PointCloudData {
  static constexpr int kPointStep = 32;
  static constexpr int kRgbOffset = 16;
  double time_s = 0;
  std::string frame_id;
  int width = 0, height = 0;
  bool is_dense = true;
  std::vector<uint8_t> data;  ///< width * height * kPointStep bytes, little-endian floats
};

/// The point cloud of a depth frame of `camera`: the point of pixel (u, v) with depth d
/// is d * K^-1 [u v 1]^T, K as in cameraInfo(); its colour is that pixel of `image` (all
/// zero when `image` has another size, as in Gazebo). Stamp and frame are the depth's.
/// @throws std::invalid_argument when `depth` does not have the camera's size.
void makePointCloud(const CameraSpec& camera, const DepthImageData& depth,
                    const ImageData& image, PointCloudData* cloud);

}  // namespace bullet_sim

#endif  // BULLET_SIM_DEPTH_CAMERA_H
