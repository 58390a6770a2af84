// Core-only speed benchmark: the round-track scenario at 1 kHz physics with
// every sensor read when due (lidar 5 Hz, IMU 200 Hz, odometry and joint
// states at the diff drive's rate, link poses for tf at the same rate), as
// fast as one core allows, while a lidar lane-keeper drives the robot round
// the track. Prints the real-time factor last.
//
// With a file of start poses (one "x y yaw" line per robot, as bench/multi_robot.py places
// them) it runs one Burger per line instead, each driving the command's circle (0.1 m/s,
// 0.3 rad/s) with every sensor read, and checks that each stayed on its circle.
//
// --threads N steps the physics on N threads (default: the machine's hardware threads).
//
// Usage: bullet_sim_bench [--threads N] <robot.urdf> <world.sdf> [sim_seconds [poses_file]]
#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
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

/// The circle command of bench/scenario.py and the radius it drives.
constexpr double kCircleLinearMps = 0.1, kCircleAngularRadps = 0.3;
constexpr double kCircleRadiusM = kCircleLinearMps / kCircleAngularRadps;
/// How far from its circle a robot may end, and how far its path and turn may stray from
/// v t and w t (bench/scenario.py's peers check 15 %; the circle's own creep is a few %).
constexpr double kCircleToleranceM = 0.05;
constexpr double kDriveTolerance = 0.15;

/// Path length and heading change of a robot, from its pose at each odometry reading.
struct Track {
  Eigen::Vector2d last_xy;
  double last_yaw, path_m = 0, turn_rad = 0;
  void add(const bullet_sim::Pose3& pose) {
    const Eigen::Vector2d xy = pose.position.head<2>();
    const Eigen::Vector3d x_axis = pose.orientation * Eigen::Vector3d::UnitX();
    const double yaw = std::atan2(x_axis.y(), x_axis.x());
    path_m += (xy - last_xy).norm();
    turn_rad += std::remainder(yaw - last_yaw, 2.0 * M_PI);
    last_xy = xy;
    last_yaw = yaw;
  }
};

struct Start {
  double x, y, yaw;
};

std::vector<Start> readStarts(const char* path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(std::string(path) + ": cannot read the start poses");
  std::vector<Start> starts;
  Start s;
  while (in >> s.x >> s.y >> s.yaw) starts.push_back(s);
  if (starts.empty()) throw std::runtime_error(std::string(path) + ": no \"x y yaw\" line");
  return starts;
}

/// Centre of the counter-clockwise circle a robot starting at `s` drives: on its left.
Eigen::Vector2d circleCentre(const Start& s) {
  return {s.x - kCircleRadiusM * std::sin(s.yaw), s.y + kCircleRadiusM * std::cos(s.yaw)};
}

/// Every robot drove its circle: path and turn within kDriveTolerance of v t and w t, and
/// it ends on the circle. Prints the worst of each, or why not.
bool onTheirCircles(const bullet_sim::Simulation& sim, const std::vector<Start>& starts,
                    const std::vector<std::string>& names,
                    const std::map<std::string, Track>& tracks) {
  double off_m = 0, path_error = 0, turn_error = 0;
  for (size_t i = 0; i < starts.size(); ++i) {
    const Eigen::Vector2d xy = sim.modelPose(names[i]).position.head<2>();
    off_m = std::max(off_m, std::fabs((xy - circleCentre(starts[i])).norm() - kCircleRadiusM));
    const Track& t = tracks.at(names[i]);
    const double v_t = kCircleLinearMps * sim.timeS(), w_t = kCircleAngularRadps * sim.timeS();
    path_error = std::max(path_error, std::fabs(t.path_m / v_t - 1));
    turn_error = std::max(turn_error, std::fabs(t.turn_rad / w_t - 1));
  }
  std::printf("%zu robots on their circles: largest distance off a circle %.3f m, path %.1f %%, "
              "turn %.1f %% off v t and w t\n",
              starts.size(), off_m, 100 * path_error, 100 * turn_error);
  const bool drove = path_error <= kDriveTolerance && turn_error <= kDriveTolerance;
  if (drove && off_m <= kCircleToleranceM) return true;
  std::fprintf(stderr, "sanity check failed: a robot did not drive its circle\n");
  return false;
}

/// Takes "--threads N" out of the arguments; 0 (the machine's threads) without it.
unsigned takeThreads(int* argc, char** argv) {
  for (int i = 1; i + 1 < *argc; ++i) {
    if (std::string(argv[i]) != "--threads") continue;
    const int n = std::atoi(argv[i + 1]);
    if (n < 1) throw std::invalid_argument(std::string("--threads: not a count >= 1: ") + argv[i + 1]);
    for (int j = i; j + 2 < *argc; ++j) argv[j] = argv[j + 2];
    *argc -= 2;
    return static_cast<unsigned>(n);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  bullet_sim::SimConfig cfg;
  try {
    cfg.threads = takeThreads(&argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s [--threads N] <robot.urdf> <world.sdf> [sim_seconds [poses_file]]\n",
                 argv[0]);
    return 2;
  }
  const double sim_seconds = argc > 3 ? std::atof(argv[3]) : 60.0;
  try {
    const bullet_sim::RobotSpec robot = bullet_sim::parseRobotFile(argv[1]);
    const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(argv[2]);
    bullet_sim::Simulation sim(world, cfg);
    std::printf("threads: %u\n", sim.threads());
    const std::vector<Start> starts =
        argc > 4 ? readStarts(argv[4]) : std::vector<Start>{{0.0, 0.0, 1.5675}};
    const bool circles = argc > 4;
    std::vector<std::string> robot_names;
    std::map<std::string, Track> tracks;
    for (size_t i = 0; i < starts.size(); ++i) {
      robot_names.push_back(i == 0 ? "robot" : "robot_" + std::to_string(i + 1));
      bullet_sim::Pose3 spawn;
      spawn.position = Eigen::Vector3d(starts[i].x, starts[i].y, 0.0);
      spawn.orientation = Eigen::AngleAxisd(starts[i].yaw, Eigen::Vector3d::UnitZ());
      sim.spawnRobot(robot_names.back(), robot, spawn);
      if (circles) sim.setCmdVel(robot_names.back(), kCircleLinearMps, kCircleAngularRadps);
      tracks[robot_names.back()] = Track{Eigen::Vector2d(starts[i].x, starts[i].y), starts[i].yaw};
    }

    using Clock = std::chrono::steady_clock;
    size_t reads[5] = {0, 0, 0, 0, 0};
    double read_s[5] = {0, 0, 0, 0, 0};
    double physics_s = 0, checksum = 0;
    const std::clock_t cpu_start = std::clock();
    const auto start = Clock::now();
    while (sim.timeS() < sim_seconds) {
      const auto before_step = Clock::now();
      // As the node steps: to the next reading, at most 5 ms of sim time at a time.
      const std::vector<bullet_sim::DueSensor> due_now = sim.stepToNextReading(5);
      auto t = Clock::now();
      physics_s += std::chrono::duration<double>(t - before_step).count();
      // As the node reads: the due scans together (on the physics threads), then the rest.
      std::vector<bullet_sim::DueSensor> rays;
      for (const bullet_sim::DueSensor& due : due_now) {
        if (due.kind == bullet_sim::SensorKind::Ray && due.robot.rfind("robot", 0) == 0) {
          rays.push_back(due);
        }
      }
      if (!rays.empty()) {
        for (const bullet_sim::LaserScanData& scan : sim.readRays(rays)) {
          if (circles) {
            checksum += static_cast<double>(std::count_if(
                scan.ranges.begin(), scan.ranges.end(), [](float r) { return std::isfinite(r); }));
          } else {
            steer(&sim, scan);
          }
        }
        reads[static_cast<int>(bullet_sim::SensorKind::Ray)] += rays.size();
        const auto after = Clock::now();
        read_s[static_cast<int>(bullet_sim::SensorKind::Ray)] +=
            std::chrono::duration<double>(after - t).count();
        t = after;
      }
      for (const bullet_sim::DueSensor& due : due_now) {
        if (due.robot.rfind("robot", 0) != 0) continue;  // the world's movable models
        if (due.kind == bullet_sim::SensorKind::Ray) continue;
        const int kind = static_cast<int>(due.kind);
        if (kind >= 5) continue;  // the plugins' readings: the bench's robots have none
        ++reads[kind];
        switch (due.kind) {
          case bullet_sim::SensorKind::Ray:
            break;
          case bullet_sim::SensorKind::Imu:
            checksum += sim.readImu(due.robot, due.index).linear_acceleration.z();
            break;
          case bullet_sim::SensorKind::Odometry:
            checksum += sim.readOdometry(due.robot).pose.position.x();
            tracks[due.robot].add(sim.modelPose(due.robot));
            checksum += sim.linkPoses(due.robot).size();
            break;
          case bullet_sim::SensorKind::JointStates:
            checksum += sim.readJointStates(due.robot).positions.at(0);
            break;
          case bullet_sim::SensorKind::Camera:
            break;
          default:
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
    if (circles && !onTheirCircles(sim, starts, robot_names, tracks)) return 1;
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
