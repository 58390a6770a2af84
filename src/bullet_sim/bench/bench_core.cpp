// Core-only speed benchmark: the round-track scenario at 1 kHz physics with
// every sensor read when due (lidar 5 Hz, IMU 200 Hz, odometry and joint
// states at the diff drive's rate, link poses for tf at the same rate), as
// fast as one core allows, while a lidar lane-keeper drives the robot round
// the track. Prints the real-time factor last.
//
// Usage: bullet_sim_bench <robot.urdf> <world.sdf> [sim_seconds]
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"

namespace {

/// Smallest range of the rays between two angles (degrees, counter-clockwise).
double minRange(const bullet_sim::LaserScanData& scan, double from_deg, double to_deg) {
  double best = scan.range_max;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const double deg = std::remainder(
        (scan.angle_min + i * scan.angle_increment) * 180.0 / M_PI - from_deg, 360.0);
    const double span = std::remainder(to_deg - from_deg, 360.0);
    if (deg >= 0 && deg <= span && std::isfinite(scan.ranges[i])) {
      best = std::min(best, static_cast<double>(scan.ranges[i]));
    }
  }
  return best;
}

/// Keeps to the middle of the lane and turns away from a wall ahead.
void steer(bullet_sim::Simulation* sim, const bullet_sim::LaserScanData& scan) {
  const double left = minRange(scan, 60, 120), right = minRange(scan, 240, 300);
  const double front = minRange(scan, -25, 25);
  if (front < 0.45) {
    sim->setCmdVel("robot", 0.03, left > right ? 1.0 : -1.0);
  } else {
    sim->setCmdVel("robot", 0.2, std::clamp(1.5 * (left - right), -1.0, 1.0));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <robot.urdf> <world.sdf> [sim_seconds]\n", argv[0]);
    return 2;
  }
  const double sim_seconds = argc > 3 ? std::atof(argv[3]) : 60.0;
  try {
    const bullet_sim::RobotSpec robot = bullet_sim::parseRobotFile(argv[1]);
    const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(argv[2]);
    bullet_sim::Simulation sim(world, bullet_sim::SimConfig());
    bullet_sim::Pose3 spawn;
    spawn.orientation = Eigen::AngleAxisd(1.5675, Eigen::Vector3d::UnitZ());
    sim.spawnRobot("robot", robot, spawn);

    using Clock = std::chrono::steady_clock;
    size_t reads[5] = {0, 0, 0, 0, 0};
    double read_s[5] = {0, 0, 0, 0, 0};
    double physics_s = 0, checksum = 0;
    const std::clock_t cpu_start = std::clock();
    const auto start = Clock::now();
    while (sim.timeS() < sim_seconds) {
      const auto before_step = Clock::now();
      const std::vector<bullet_sim::DueSensor> due_now = sim.step();
      auto t = Clock::now();
      physics_s += std::chrono::duration<double>(t - before_step).count();
      for (const bullet_sim::DueSensor& due : due_now) {
        if (due.robot != "robot") continue;  // the world's movable models have no sensors
        const int kind = static_cast<int>(due.kind);
        ++reads[kind];
        switch (due.kind) {
          case bullet_sim::SensorKind::Ray:
            steer(&sim, sim.readRay(due.robot, due.index));
            break;
          case bullet_sim::SensorKind::Imu:
            checksum += sim.readImu(due.robot, due.index).linear_acceleration.z();
            break;
          case bullet_sim::SensorKind::Odometry:
            checksum += sim.readOdometry(due.robot).pose.position.x();
            checksum += sim.linkPoses(due.robot).size();
            break;
          case bullet_sim::SensorKind::JointStates:
            checksum += sim.readJointStates(due.robot).positions.at(0);
            break;
          case bullet_sim::SensorKind::Camera:
            break;
        }
        const auto after = Clock::now();
        read_s[kind] += std::chrono::duration<double>(after - t).count();
        t = after;
      }
    }
    const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    const double cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    const char* names[5] = {"lidar", "imu", "camera", "odometry+link poses", "joint states"};
    std::printf("physics: %.2f us per %.0f us step\n", 1e6 * physics_s / (sim.timeS() / 1e-3),
                1e3);
    for (int k = 0; k < 5; ++k) {
      if (reads[k] == 0) continue;
      std::printf("%s: %zu reads, %.2f us each, %.1f%% of the run\n", names[k], reads[k],
                  1e6 * read_s[k] / reads[k], 100.0 * read_s[k] / wall_s);
    }
    const bullet_sim::Pose3 end = sim.modelPose("robot");
    std::printf("robot at x %.2f y %.2f after the run (checksum %g)\n", end.position.x(),
                end.position.y(), checksum);
    std::printf("process CPU time %.3f s: real-time factor per CPU second %.1f\n", cpu_s,
                sim.timeS() / cpu_s);
    std::printf("sim %.1f s in %.3f s wall: real-time factor %.1f\n", sim.timeS(), wall_s,
                sim.timeS() / wall_s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
