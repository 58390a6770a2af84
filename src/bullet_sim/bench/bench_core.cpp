// Core-only speed benchmark: the round-track scenario at 1 kHz physics with
// every sensor read when due (lidar 5 Hz, IMU 200 Hz, odometry and joint
// states at the diff drive's rate, link poses for tf at the same rate), as
// fast as one core allows. Prints the real-time factor last.
//
// Usage: bullet_sim_bench <robot.urdf> <world.sdf> [sim_seconds]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"

namespace {

std::string readFile(const char* path) {
  std::ifstream in(path);
  if (!in) throw bullet_sim::LoadError(std::string(path) + ": cannot read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <robot.urdf> <world.sdf> [sim_seconds]\n", argv[0]);
    return 2;
  }
  const double sim_seconds = argc > 3 ? std::atof(argv[3]) : 60.0;
  try {
    const bullet_sim::RobotSpec robot = bullet_sim::parseRobot(readFile(argv[1]), argv[1]);
    const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(argv[2]);
    bullet_sim::Simulation sim(world, bullet_sim::SimConfig());
    bullet_sim::Pose3 spawn;
    spawn.orientation = Eigen::AngleAxisd(1.5675, Eigen::Vector3d::UnitZ());
    sim.spawnRobot("robot", robot, spawn);

    size_t reads[5] = {0, 0, 0, 0, 0};
    double checksum = 0;
    const auto start = std::chrono::steady_clock::now();
    while (sim.timeS() < sim_seconds) {
      // A slow weave so that contacts, motors and the flag all stay busy.
      sim.setCmdVel("robot", 0.1, 0.5 * std::sin(sim.timeS()));
      for (const bullet_sim::DueSensor& due : sim.step()) {
        ++reads[static_cast<int>(due.kind)];
        switch (due.kind) {
          case bullet_sim::SensorKind::Ray:
            checksum += sim.readRay(due.robot, due.index).ranges[0];
            break;
          case bullet_sim::SensorKind::Imu:
            checksum += sim.readImu(due.robot, due.index).linear_acceleration.z();
            break;
          case bullet_sim::SensorKind::Odometry:
            checksum += sim.readOdometry(due.robot).pose.position.x();
            checksum += sim.linkPoses(due.robot).size();
            break;
          case bullet_sim::SensorKind::JointStates:
            checksum += sim.readJointStates(due.robot).positions[0];
            break;
          case bullet_sim::SensorKind::Camera:
            break;
        }
      }
    }
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("reads: ray %zu, imu %zu, odom %zu, joint_states %zu (checksum %g)\n", reads[0],
                reads[1], reads[3], reads[4], checksum);
    std::printf("sim %.1f s in %.3f s wall: real-time factor %.1f\n", sim.timeS(), wall_s,
                sim.timeS() / wall_s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
