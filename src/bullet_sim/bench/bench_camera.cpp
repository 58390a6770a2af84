// Camera cost inside the simulation: the round-track scenario at 1 kHz physics, driving a
// slow weave, run twice on one core: once without the camera, once rendering every camera
// frame when it falls due (the Burger's: 640 x 480 at 30 Hz). Prints the per-frame render
// time (median, 95th percentile, max) and both real-time factors. A depth camera's frame
// is timed with its depth image and point cloud (both made each frame, as for a subscriber
// to each).
//
// With --cameras N, N robots instead (at most 16, on the round track's west lane, 4 rows of
// 4 as bullet_sim_bench puts them), on a simulation of --threads T (default 2): their
// cameras fall due at the same steps, and each time they are rendered both one by one
// (render()) and together (renderTogether(), on the simulation's threads), alternately
// first. Prints the median time of each way per time they fall due.
//
// With --save-frame FILE, the last colour frame of the single camera is written to FILE
// (binary PPM), for a look or a check of what was drawn. With --spawn X,Y,YAW the single
// robot starts there instead of at the round track's spawn pose (0, 0, 1.5675). Warnings
// of the world and of the renderer (a texture that could not be read, say) are printed as
// "warning: ..." lines.
//
// Usage: bullet_sim_camera_bench [--cameras N [--threads T]] [--save-frame FILE]
//                                [--spawn X,Y,YAW] <robot.urdf> <world.sdf> [sim_seconds]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "bullet_sim/errors.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/render/depth_camera.h"
#include "bullet_sim/simulation.h"
#include "sim_render/image_io.h"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Run {
  double wall_s = 0, sim_s = 0;
  bullet_sim::ImageData last_image;
  std::vector<std::string> warnings;  ///< the renderer's
  std::vector<double> frame_ms;
  std::vector<double> cloud_ms;  ///< a depth camera's point cloud, made after its frame
};

/// Where the single robot starts: x, y (m) and yaw (rad); the round track's spawn pose by
/// default.
struct Start {
  double x_m = 0, y_m = 0, yaw_rad = 1.5675;
};

Run runScenario(const bullet_sim::WorldSpec& world, const bullet_sim::RobotSpec& robot,
                const Start& start_pose, double sim_seconds, bool render) {
  bullet_sim::Simulation sim(world, bullet_sim::SimConfig());
  bullet_sim::Pose3 spawn;
  spawn.position = Eigen::Vector3d(start_pose.x_m, start_pose.y_m, 0);
  spawn.orientation = Eigen::AngleAxisd(start_pose.yaw_rad, Eigen::Vector3d::UnitZ());
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
  run.last_image = std::move(image);
  run.warnings = renderer.warnings();
  return run;
}

/// The frame as a binary PPM (rgb8; other encodings are refused).
void writeFrame(const std::string& path, const bullet_sim::ImageData& image) {
  if (image.encoding != "rgb8") {
    throw std::invalid_argument("--save-frame: the camera's frames are " + image.encoding +
                                ", not rgb8");
  }
  sim_render::writePpm(path, image.width, image.height, image.data);
}

double percentile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(q * static_cast<double>(values.size() - 1))];
}

/// Milliseconds per time the cameras fell due, rendered one way and the other.
struct Together {
  std::vector<double> one_by_one_ms, together_ms;
  size_t frames = 0;  ///< per time
};

/// The cameras of `n` copies of `robot`, driving slow weaves, rendered both ways each time
/// they are due (see the file comment).
Together runTogether(const bullet_sim::WorldSpec& world, const bullet_sim::RobotSpec& robot,
                     int n, unsigned threads, double sim_seconds) {
  bullet_sim::SimConfig cfg;
  cfg.threads = threads;
  bullet_sim::Simulation sim(world, cfg);
  const double xs[4] = {-0.55, -0.25, 0.05, 0.35}, ys[4] = {-1.4, -0.95, 0.3, 0.75};
  for (int i = 0; i < n; ++i) {
    bullet_sim::Pose3 spawn;
    spawn.position = Eigen::Vector3d(xs[i % 4], ys[i / 4], 0);
    spawn.orientation = Eigen::AngleAxisd((i / 4) % 2 ? -M_PI_2 : M_PI_2, Eigen::Vector3d::UnitZ());
    sim.spawnRobot("robot" + std::to_string(i), robot, spawn);
  }
  bullet_sim::CameraRenderer alone(sim), with_others(sim);
  std::vector<bullet_sim::ImageData> images(n * robot.cameras.size());
  std::vector<bullet_sim::DepthImageData> depths(images.size());
  Together run;
  while (sim.timeS() < sim_seconds) {
    for (int i = 0; i < n; ++i) {
      sim.setCmdVel("robot" + std::to_string(i), 0.05, 0.3 * std::sin(sim.timeS() + i));
    }
    std::vector<bullet_sim::CameraFrame> frames;
    for (const bullet_sim::DueSensor& due : sim.stepToNextReading(5)) {
      if (due.kind != bullet_sim::SensorKind::Camera) continue;
      const size_t k = frames.size();
      const bool depth = robot.cameras[due.index].depth.has_value();
      frames.push_back({due.robot, due.index, &images[k], depth ? &depths[k] : nullptr, {}});
    }
    if (frames.empty()) continue;
    run.frames = frames.size();
    const auto oneByOne = [&] {
      const Clock::time_point start = Clock::now();
      for (const bullet_sim::CameraFrame& f : frames) {
        alone.render(f.robot, f.index, f.image, f.depth);
      }
      run.one_by_one_ms.push_back(1e3 * secondsSince(start));
    };
    const auto together = [&] {
      const Clock::time_point start = Clock::now();
      with_others.renderTogether(&frames);
      run.together_ms.push_back(1e3 * secondsSince(start));
      for (const bullet_sim::CameraFrame& f : frames) {
        if (f.error) std::rethrow_exception(f.error);
      }
    };
    if (run.together_ms.size() % 2 == 0) {
      oneByOne();
      together();
    } else {
      together();
      oneByOne();
    }
  }
  return run;
}

int benchTogether(const bullet_sim::RobotSpec& robot, const bullet_sim::WorldSpec& world, int n,
                  unsigned threads, double sim_seconds) {
  if (n < 1 || n > 16) throw std::invalid_argument("--cameras: 1 to 16 robots");
  const Together run = runTogether(world, robot, n, threads, sim_seconds);
  if (run.together_ms.empty()) throw bullet_sim::LoadError("the cameras were never due");
  const double one = percentile(run.one_by_one_ms, 0.5), both = percentile(run.together_ms, 0.5);
  std::printf("%d robots, %zu camera frames due at a time, %zu times in %.1f s sim\n", n,
              run.frames, run.together_ms.size(), sim_seconds);
  std::printf("one by one: median %.3f ms (p95 %.3f)\n", one, percentile(run.one_by_one_ms, 0.95));
  std::printf("together on %u threads: median %.3f ms (p95 %.3f), %.2fx\n", threads, both,
              percentile(run.together_ms, 0.95), one / both);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int cameras = 0;
  unsigned threads = 2;
  std::string save_frame;
  Start start;
  int arg = 1;
  bool usable = true;
  for (; arg < argc && std::strncmp(argv[arg], "--", 2) == 0; arg += 2) {
    const bool valued = arg + 1 < argc && std::atoi(argv[arg + 1]) > 0;
    if (arg + 1 < argc && std::strcmp(argv[arg], "--save-frame") == 0) {
      save_frame = argv[arg + 1];
    } else if (arg + 1 < argc && std::strcmp(argv[arg], "--spawn") == 0) {
      char end = 0;
      usable = std::sscanf(argv[arg + 1], "%lf,%lf,%lf%c", &start.x_m, &start.y_m,
                           &start.yaw_rad, &end) == 3;
      if (!usable) break;
    } else if (valued && std::strcmp(argv[arg], "--cameras") == 0) {
      cameras = std::atoi(argv[arg + 1]);
    } else if (valued && std::strcmp(argv[arg], "--threads") == 0) {
      threads = static_cast<unsigned>(std::atoi(argv[arg + 1]));
    } else {
      usable = false;
      break;
    }
  }
  if (!usable || argc - arg < 2) {
    std::fprintf(stderr,
                 "usage: %s [--cameras N [--threads T]] [--save-frame FILE] [--spawn X,Y,YAW] "
                 "<robot.urdf> <world.sdf> [sim_seconds]\n",
                 argv[0]);
    return 2;
  }
  const char* robot_file = argv[arg];
  const double sim_seconds = argc - arg > 2 ? std::atof(argv[arg + 2]) : 20.0;
  try {
    const bullet_sim::RobotSpec robot = bullet_sim::parseRobotFile(robot_file);
    const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(argv[arg + 1]);
    if (robot.cameras.empty()) throw bullet_sim::LoadError(std::string(robot_file) + ": no camera");
    for (const std::string& warning : world.warnings) std::printf("warning: %s\n", warning.c_str());
    if (cameras > 0) return benchTogether(robot, world, cameras, threads, sim_seconds);
    const bullet_sim::CameraSpec& camera = robot.cameras[0];
    const Run plain = runScenario(world, robot, start, sim_seconds, false);
    const Run with_camera = runScenario(world, robot, start, sim_seconds, true);
    const std::vector<double>& ms = with_camera.frame_ms;
    if (ms.empty()) throw bullet_sim::LoadError("the camera was never due");
    for (const std::string& warning : with_camera.warnings) {
      std::printf("warning: %s\n", warning.c_str());
    }
    if (!save_frame.empty()) writeFrame(save_frame, with_camera.last_image);
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
