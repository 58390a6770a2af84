#ifndef BULLET_SIM_CORE_LENS_CAMERA_H
#define BULLET_SIM_CORE_LENS_CAMERA_H

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Geometry>
#include <sim_render/renderer.h>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// A wide-angle camera drawn as Gazebo's WideAngleCamera draws it: the scene is rendered
/// into a cube map around the camera (pinhole faces of 90 degrees, env_texture_size pixels
/// square), then each output pixel takes the cube-map texel (nearest) in the direction the
/// lens maps it to (CameraLens); pixels beyond the cutoff angle are black.
///
/// Which face each output pixel samples is worked out once, at construction, and only the
/// faces some pixel samples are ever rendered (five, without the one behind, while the
/// lens's largest angle stays below about 135 degrees). Not thread-safe.
class LensCamera {
 public:
  /// @throws std::invalid_argument for a camera without a lens, or one CameraLens or
  /// sim_render::CameraModel rejects.
  explicit LensCamera(const CameraSpec& camera);
  ~LensCamera();

  /// Draws `scene` seen from `T_world_camera` (Gazebo convention: x ahead, y left, z up)
  /// into `out_rgb8`, resized to width * height * 3, row 0 on top.
  void render(const sim_render::Scene& scene, const Eigen::Isometry3d& T_world_camera,
              std::vector<std::uint8_t>& out_rgb8);

  /// How many cube faces a frame renders (1..6; 0 when every pixel is beyond the cutoff).
  int facesRendered() const;

 private:
  struct Face {
    Eigen::Matrix3d R_camera_face;
    std::unique_ptr<sim_render::Renderer> renderer;  ///< null for a face no pixel samples
    std::vector<std::uint8_t> rgb;
  };
  /// Where an output pixel takes its colour: face index (-1: black) and byte offset in it.
  struct Sample {
    int face = -1;
    std::uint32_t offset = 0;
  };

  void buildSamples(const CameraSpec& camera);

  int width_ = 0, height_ = 0;
  std::array<Face, 6> faces_;
  std::vector<Sample> samples_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_LENS_CAMERA_H
