// Frame time of the round-track scene (ground, 21 walls, start line, a ~30-primitive robot)
// at the spawn pose, 640 x 480, on one core; then the same with a second robot in view.
// Not a test: it prints figures.
//   render_bench [frames (default 200)] [image path prefix] [robot y offset in m (default 0)]
// With a prefix it writes <prefix>_spawn.ppm and <prefix>_second_robot.ppm.
#include "../test/round_track_scene.h"
#include "sim_render/image_io.h"
#include "sim_render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace sim_render;

// Renders `frames` frames and prints median / min / max milliseconds.
void timeFrames(const char* label, const Scene& scene, const Eigen::Isometry3d& T_world_camera, int frames,
                Renderer& renderer, std::vector<std::uint8_t>& image) {
  renderer.render(scene, T_world_camera, image);  // warm-up: sizes the buffers
  std::vector<double> ms(frames);
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(scene, T_world_camera, image);
    ms[i] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  std::sort(ms.begin(), ms.end());
  const RenderStats& stats = renderer.lastStats();
  std::printf("render_bench: %s: %zu shapes, %zu drawn, %zu triangles rasterized (%zu near-clipped)\n", label,
              scene.size(), stats.shapes_drawn, stats.triangles_drawn, stats.triangles_clipped);
  std::printf("render_bench: %s: %d frames %dx%d: median %.3f ms, min %.3f ms, max %.3f ms\n", label, frames,
              renderer.camera().width, renderer.camera().height, ms[ms.size() / 2], ms.front(), ms.back());
}

void writeImage(const std::string& path, const CameraModel& camera, const std::vector<std::uint8_t>& image) {
  writePpm(path, camera.width, camera.height, image);
  std::printf("render_bench: wrote %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 200;
  if (frames < 1) {
    std::fprintf(stderr, "render_bench: frames must be >= 1, got '%s'\n", argv[1]);
    return 2;
  }
  const double robot_y_m = argc > 3 ? std::atof(argv[3]) : 0.0;
  Scene scene;
  round_track::addWorld(scene);
  const Eigen::Isometry3d T_world_base = round_track::baseLinkPose(0, robot_y_m, round_track::kSpawnYaw_rad);
  round_track::addRobot(scene, T_world_base);
  const Eigen::Isometry3d T_world_camera = round_track::cameraPose(T_world_base);
  std::printf("render_bench: robot at (0, %.3f), yaw %.4f\n", robot_y_m, round_track::kSpawnYaw_rad);

  CameraModel camera;  // 640 x 480, hfov 1.5707, clip 0.02 .. 100 (the Burger's camera)
  Renderer renderer(camera);
  std::vector<std::uint8_t> image;
  timeFrames("spawn", scene, T_world_camera, frames, renderer, image);
  if (argc > 2) writeImage(std::string(argv[2]) + "_spawn.ppm", camera, image);

  // A second robot 0.8 m ahead, turned towards the camera, fills part of the view.
  Scene busy;
  round_track::addWorld(busy);
  round_track::addRobot(busy, T_world_base);
  round_track::addRobot(busy, round_track::baseLinkPose(0, robot_y_m + 0.8, round_track::kSpawnYaw_rad + 2.5));
  std::vector<std::uint8_t> busy_image;
  timeFrames("second robot in view", busy, T_world_camera, frames, renderer, busy_image);
  if (argc > 2) writeImage(std::string(argv[2]) + "_second_robot.ppm", camera, busy_image);
  return 0;
}
