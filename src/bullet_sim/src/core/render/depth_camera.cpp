#include "bullet_sim/render/depth_camera.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace bullet_sim {

void makePointCloud(const CameraSpec& camera, const DepthImageData& depth,
                    const ImageData& image, PointCloudData* cloud) {
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  if (depth.width != camera.width || depth.height != camera.height ||
      depth.depth_m.size() != pixels) {
    throw std::invalid_argument("makePointCloud: a " + std::to_string(depth.width) + "x" +
                                std::to_string(depth.height) + " depth frame for the " +
                                std::to_string(camera.width) + "x" +
                                std::to_string(camera.height) + " camera '" + camera.name + "'");
  }
  const std::array<double, 9> K = cameraInfo(camera, 0).K;
  const double fx = K[0], cx = K[2], fy = K[4], cy = K[5];
  const size_t channels = image.data.size() == pixels * 3 ? 3 : image.data.size() == pixels ? 1 : 0;

  cloud->time_s = depth.time_s;
  cloud->frame_id = depth.frame_id;
  cloud->width = camera.width;
  cloud->height = camera.height;
  cloud->is_dense = true;
  // Row by row into a buffer that stays in the cache, appended to reserved storage: the
  // cloud's bytes are written once, not zeroed first.
  std::vector<float> x_per_m(static_cast<size_t>(camera.width));
  for (int u = 0; u < camera.width; ++u) x_per_m[u] = static_cast<float>((u - cx) / fx);
  const size_t row_bytes = static_cast<size_t>(camera.width) * PointCloudData::kPointStep;
  std::vector<uint8_t> row(row_bytes, 0);
  cloud->data.clear();
  cloud->data.reserve(pixels * PointCloudData::kPointStep);
  for (int v = 0; v < camera.height; ++v) {
    const float y_per_m = static_cast<float>((v - cy) / fy);
    const size_t first = static_cast<size_t>(v) * camera.width;
    for (int u = 0; u < camera.width; ++u) {
      const size_t i = first + u;
      uint8_t* point = &row[static_cast<size_t>(u) * PointCloudData::kPointStep];
      const float d = depth.depth_m[i];
      if (std::isnan(d)) cloud->is_dense = false;
      const float xyz[3] = {d * x_per_m[u], d * y_per_m, d};
      std::memcpy(point, xyz, sizeof(xyz));
      uint8_t* rgb = point + PointCloudData::kRgbOffset;
      if (channels == 3) {
        std::memcpy(rgb, &image.data[3 * i], 3);
      } else if (channels == 1) {
        rgb[0] = rgb[1] = rgb[2] = image.data[i];
      }
    }
    cloud->data.insert(cloud->data.end(), row.begin(), row.end());
  }
}

}  // namespace bullet_sim
