// Frame time of the round-track scene (ground, 21 walls, start line, a ~30-primitive robot)
// at the spawn pose, 640 x 480, on one core. Not a test: it prints figures.
//   render_bench [frames (default 200)] [output.ppm]
#include "../test/round_track_scene.h"
#include "sim_render/image_io.h"
#include "sim_render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace sim_render;
  const int frames = argc > 1 ? std::atoi(argv[1]) : 200;
  if (frames < 1) {
    std::fprintf(stderr, "render_bench: frames must be >= 1, got '%s'\n", argv[1]);
    return 2;
  }
  Scene scene;
  round_track::addWorld(scene);
  const Eigen::Isometry3d T_world_base = round_track::baseLinkPose(0, 0, round_track::kSpawnYaw_rad);
  const int robot_shapes = round_track::addRobot(scene, T_world_base);
  const Eigen::Isometry3d T_world_camera = round_track::cameraPose(T_world_base);

  CameraModel camera;  // 640 x 480, hfov 1.5707, clip 0.02 .. 100 (the Burger's camera)
  Renderer renderer(camera);
  std::vector<std::uint8_t> image;
  renderer.render(scene, T_world_camera, image);  // warm-up: sizes the buffers

  std::vector<double> ms(frames);
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(scene, T_world_camera, image);
    ms[i] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  std::sort(ms.begin(), ms.end());
  const RenderStats& stats = renderer.lastStats();
  std::printf("render_bench: %dx%d, %zu shapes (%d robot), %zu shapes / %zu triangles drawn (%zu clipped)\n",
              camera.width, camera.height, scene.size(), robot_shapes, stats.shapes_drawn,
              stats.triangles_drawn, stats.triangles_clipped);
  std::printf("render_bench: %d frames: median %.3f ms, min %.3f ms, max %.3f ms\n", frames,
              ms[ms.size() / 2], ms.front(), ms.back());
  if (argc > 2) {
    writePpm(argv[2], camera.width, camera.height, image);
    std::printf("render_bench: wrote %s\n", argv[2]);
  }
  return 0;
}
