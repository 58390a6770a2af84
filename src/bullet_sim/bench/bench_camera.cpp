// Camera cost inside the simulation: the round-track scenario at 1 kHz physics, driving a
// slow weave, run twice on one core: once without the camera, once rendering every camera
// frame when it falls due (the Burger's: 640 x 480 at 30 Hz). Prints the per-frame render
// time (median, 95th percentile, max) and both real-time factors. A depth camera's frame
// is timed with its depth image and point cloud (both made each frame, as for a subscriber
// to each).
//
// Usage: bullet_sim_camera_bench <robot.urdf> <world.sdf> [sim_seconds]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bullet_sim/errors.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/render/depth_camera.h"
#include "bullet_sim/simulation.h"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Run {
  double wall_s = 0, sim_s = 0;
  std::vector<double> frame_ms;
  std::vector<double> cloud_ms;  ///< a depth camera's point cloud, made after its frame
};

Run runScenario(const bullet_sim::WorldSpec& world, const bullet_sim::RobotSpec& robot,
                double sim_seconds, bool render) {
  bullet_sim::Simulation sim(world, bullet_sim::SimConfig());
  bullet_sim::Pose3 spawn;
  spawn.orientation = Eigen::AngleAxisd(1.5675, Eigen::Vector3d::UnitZ());
  sim.spawnRobot("robot", robot, spawn);
  bullet_sim::CameraRenderer renderer(sim);
  bullet_sim::ImageData image;
  bullet_sim::DepthImageData depth;
  bullet_sim::PointCloudData cloud;
  Run run;
  const Clock::time_point start = Clock::now();
  while (sim.timeS() < sim_seconds) {
    sim.setCmdVel("robot", 0.1, 0.5 * std::sin(sim.timeS()));
    for (const bullet_sim::DueSensor& due : sim.step()) {
      if (!render || due.kind != bullet_sim::SensorKind::Camera) continue;
      const Clock::time_point frame_start = Clock::now();
      const bullet_sim::CameraSpec& camera = robot.cameras[due.index];
      renderer.render(due.robot, due.index, &image, camera.depth ? &depth : nullptr);
      run.frame_ms.push_back(1e3 * secondsSince(frame_start));
      if (!camera.depth) continue;
      const Clock::time_point cloud_start = Clock::now();
      bullet_sim::makePointCloud(camera, depth, image, &cloud);
      run.cloud_ms.push_back(1e3 * secondsSince(cloud_start));
    }
  }
  run.wall_s = secondsSince(start);
  run.sim_s = sim.timeS();
  return run;
}

double percentile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(q * static_cast<double>(values.size() - 1))];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <robot.urdf> <world.sdf> [sim_seconds]\n", argv[0]);
    return 2;
  }
  const double sim_seconds = argc > 3 ? std::atof(argv[3]) : 20.0;
  try {
    const bullet_sim::RobotSpec robot = bullet_sim::parseRobotFile(argv[1]);
    const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(argv[2]);
    if (robot.cameras.empty()) throw bullet_sim::LoadError(std::string(argv[1]) + ": no camera");
    const bullet_sim::CameraSpec& camera = robot.cameras[0];
    const Run plain = runScenario(world, robot, sim_seconds, false);
    const Run with_camera = runScenario(world, robot, sim_seconds, true);
    const std::vector<double>& ms = with_camera.frame_ms;
    if (ms.empty()) throw bullet_sim::LoadError("the camera was never due");
    std::printf("%s '%s': %d x %d %s at %g Hz, %zu frames in %.1f s sim\n",
                camera.depth ? "depth camera (frame and depth image)" : "camera",
                camera.name.c_str(), camera.width, camera.height, camera.format.c_str(),
                camera.update_rate_hz, ms.size(), with_camera.sim_s);
    std::printf("frame render: median %.3f ms, p95 %.3f ms, max %.3f ms\n", percentile(ms, 0.5),
                percentile(ms, 0.95), percentile(ms, 1.0));
    if (!with_camera.cloud_ms.empty()) {
      const std::vector<double>& cloud = with_camera.cloud_ms;
      std::printf("point cloud: median %.3f ms, p95 %.3f ms, max %.3f ms\n",
                  percentile(cloud, 0.5), percentile(cloud, 0.95), percentile(cloud, 1.0));
    }
    std::printf("real-time factor: %.1f without camera, %.1f with camera\n",
                plain.sim_s / plain.wall_s, with_camera.sim_s / with_camera.wall_s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
