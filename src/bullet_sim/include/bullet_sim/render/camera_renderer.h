#ifndef BULLET_SIM_CAMERA_RENDERER_H
#define BULLET_SIM_CAMERA_RENDERER_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/simulation.h"

namespace bullet_sim {

struct DepthImageData;

/// One camera image, laid out as sensor_msgs/Image.
struct ImageData {
  double time_s = 0;
  std::string frame_id;
  int width = 0, height = 0;
  std::string encoding;  ///< "rgb8", "bgr8", "mono8", "rgb16" or "mono16"
  int step = 0;          ///< bytes per row
  std::vector<uint8_t> data;
};

/// Intrinsics of a camera, laid out as sensor_msgs/CameraInfo.
struct CameraInfoData {
  double time_s = 0;
  std::string frame_id;
  int width = 0, height = 0;
  std::string distortion_model = "plumb_bob";
  std::array<double, 5> D{};                      ///< k1 k2 t1 t2 k3
  std::array<double, 9> K{};                      ///< row-major
  std::array<double, 9> R{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::array<double, 12> P{};                     ///< [K | 0], row-major
};

/// The ROS encoding of a Gazebo image format (R8G8B8 -> rgb8, B8G8R8 -> bgr8, L8 -> mono8,
/// R16G16B16 -> rgb16, L16 -> mono16).
/// @throws LoadError naming the camera and the format when it is not one of those.
std::string imageEncoding(const CameraSpec& camera);

/// Checks that a camera can be rendered (size, fov, clip distances, format).
/// @throws LoadError naming the camera, the field and its value.
void validateCamera(const CameraSpec& camera);

/// camera_info of a camera: fx = fy = (width / 2) / tan(hfov / 2), cx = width / 2,
/// cy = height / 2, stamped `time_s`, frame_id the plugin's frameName. For a wide-angle
/// camera fx = fy is the focal length of the pinhole that matches the lens near its axis,
/// (width / 2) * c1 * f * fun'(c3) / c2 (Gazebo's plugin would publish the pinhole formula
/// above, which is negative beyond hfov = pi). D is CameraSpec::info_distortion, P[3] =
/// -fx * hackBaseline.
CameraInfoData cameraInfo(const CameraSpec& camera, double time_s);

/// One frame of CameraRenderer::renderTogether: which camera, where its image goes and, when
/// it could not be rendered, why.
struct CameraFrame {
  std::string robot;
  size_t index = 0;                   ///< the camera's index in the robot's spec
  ImageData* image = nullptr;         ///< the frame's image, its buffer reused
  DepthImageData* depth = nullptr;    ///< a depth camera's depth image, or null for none
  std::exception_ptr error;           ///< set when the frame was not rendered: what render()
                                      ///< would have thrown
};

/// Renders the cameras of a Simulation's robots on the CPU (no display, no GPU).
///
/// The world's shapes are turned into triangles once, at construction; each robot's
/// visuals are added the first time a frame is rendered after it was spawned (and dropped
/// once it is deleted; a robot is known by its spawn generation, so one deleted and spawned
/// again under the same name is drawn as it is now), so a frame only moves the robots'
/// visuals to their current link poses and rasterizes. Every robot is drawn, including
/// the one carrying the camera (a camera inside its own housing does not see it: faces are
/// single-sided). Mesh visuals are drawn part by part, each part in its own material
/// colour or else the visual's. A wide-angle camera (CameraSpec::lens) is drawn through a
/// cube map of pinhole faces remapped by its lens (src/core/lens_camera.h). Frames due at
/// the same time are drawn together on the simulation's threads (renderTogether).
/// Not thread-safe: call it where the simulation is stepped.
class CameraRenderer {
 public:
  /// Keeps a reference to `sim`, which must outlive the renderer.
  explicit CameraRenderer(const Simulation& sim);
  ~CameraRenderer();
  CameraRenderer(const CameraRenderer&) = delete;
  CameraRenderer& operator=(const CameraRenderer&) = delete;

  /// Renders camera `index` of `robot` as the simulation stands now into `image`, whose
  /// buffer is reused from frame to frame. With `depth` (a depth camera), the same pass's
  /// depth buffer becomes the depth image, its cutoffs applied (see depth_camera.h).
  /// @throws std::out_of_range for an unknown robot or camera index, LoadError for a
  /// camera validateCamera() rejects, std::invalid_argument for `depth` with a camera
  /// that is not a depth camera.
  void render(const std::string& robot, size_t index, ImageData* image,
              DepthImageData* depth = nullptr);

  /// Renders several cameras as the simulation stands now: the scene's robots are brought
  /// up to date and posed once, then each frame is drawn with its camera's own buffers, on
  /// the simulation's threads (Simulation::runInParallel), the scene only read. Each frame
  /// is the same to the bit as render() gives it alone. A frame that render() would throw
  /// for gets that exception in its `error` (cleared otherwise), and the other frames are
  /// rendered all the same. Each frame needs its own image and depth image.
  /// @throws std::invalid_argument for a camera named twice (nothing is rendered then).
  void renderTogether(std::vector<CameraFrame>* frames);

  /// Visuals that could not be drawn (bad sizes), one message each; meshes that could not
  /// be read are in the robot's and the world's spec warnings instead.
  const std::vector<std::string>& warnings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CAMERA_RENDERER_H
