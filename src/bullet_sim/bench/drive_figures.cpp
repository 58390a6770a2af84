// The Burger's figures driving straight, stopping and turning on the spot, measured in the
// simulator beside what the friction model of Gazebo's ODE predicts for the same values
// (worked out by hand in test/core/burger_drive_model.h). README "Friction and drive" quotes
// its output. The robot settles for 1 s first; world time 1 s is a drive update, so each
// command is taken at once.
//
// Usage: bullet_sim_drive_figures <burger.urdf> <world.sdf> [linear_mps [angular_radps]]
// (defaults: the real Burger's limits, 0.22 m/s and 2.84 rad/s)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "bullet_sim/simulation.h"
#include "burger_drive_model.h"

namespace {

using bullet_sim::Simulation;
using namespace bullet_sim_test;

constexpr double kStepS = 0.001, kRunS = 3.0, kWithinShare = 0.99;

double yawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
}

/// What one run under a command records, step by step.
struct Run {
  double first_s = -1;       ///< when the rate came within 1 % of its command
  double rate_at_10ms = 0, rate_at_20ms = 0, rate_at_200ms = 0, rate_at_end = 0;
  double distance_m = 0, farthest_m = 0, turn_rad = 0;
};

/// Runs `seconds` under (v, w) and records the forward speed (w == 0) or yaw rate.
Run drive(Simulation* sim, double v, double w, double seconds) {
  const bullet_sim::Pose3 start = sim->modelPose("burger");
  sim->setCmdVel("burger", v, w);
  Run r;
  double last_yaw = yawOf(start.orientation);
  const long steps = std::lround(seconds / kStepS);
  for (long i = 1; i <= steps; ++i) {
    sim->step();
    const bullet_sim::Pose3 p = sim->modelPose("burger");
    const bullet_sim::Twist3 t = sim->modelTwist("burger");
    const double rate =
        w == 0 ? t.linear.dot(p.orientation * Eigen::Vector3d::UnitX()) : t.angular.z();
    const double command = w == 0 ? v : w;
    if (r.first_s < 0 && command != 0 && std::fabs(rate) >= kWithinShare * std::fabs(command)) {
      r.first_s = i * kStepS;
    }
    if (i == 10) r.rate_at_10ms = rate;
    if (i == 20) r.rate_at_20ms = rate;
    if (i == 200) r.rate_at_200ms = rate;
    r.rate_at_end = rate;
    r.farthest_m = std::max(r.farthest_m, (p.position - start.position).head<2>().norm());
    const double yaw = yawOf(p.orientation);
    r.turn_rad += std::remainder(yaw - last_yaw, 2 * M_PI);
    last_yaw = yaw;
  }
  r.distance_m = (sim->modelPose("burger").position - start.position).head<2>().norm();
  return r;
}

void row(const char* what, double hand, double measured) {
  std::printf("| %s | %.4f | %.4f |\n", what, hand, measured);
}

void straight(Simulation* sim, double v) {
  const double a = forwardLimitMps2(), b = brakingLimitMps2();
  const Run go = drive(sim, v, 0, kRunS);
  const Run stop = drive(sim, 0, 0, 1.0);
  std::printf("\nstraight at %.2f m/s for %.0f s, then stop\n\n| | ODE model | bullet_sim |\n"
              "|---|---|---|\n", v, kRunS);
  row("acceleration while the tyres slip (m/s^2)", a,
      (go.rate_at_200ms - go.rate_at_20ms) / 0.18);
  row("time to within 1 % of the command (s)", kWithinShare * v / a, go.first_s);
  row("distance (m)", v * kRunS - v * v / (2 * a), go.distance_m);
  row("final speed (m/s)", v, go.rate_at_end);
  row("heading change (rad)", 0, go.turn_rad);
  row("deceleration while stopping (m/s^2)", b, (stop.rate_at_20ms - stop.rate_at_200ms) / 0.18);
  row("stopping distance (m)", v * v / (2 * b), stop.distance_m);
}

void spin(Simulation* sim, double w) {
  const double rim = w * kHalfTrackM, alpha = spinLimitRadps2();
  const std::vector<double> steps = rimStaircase(rim);
  // The rims reach their target at the last update of the staircase; the body's yaw rate
  // follows its last step at alpha.
  const double before = steps.size() > 1 ? steps[steps.size() - 2] / kHalfTrackM : 0;
  const double reach_s = (steps.size() - 1) * kDriveUpdateS +
                         std::max(0.0, kWithinShare * w - before) / alpha;
  const Run r = drive(sim, 0, w, kRunS);
  std::printf("\non the spot at %.2f rad/s for %.0f s\n\n| | ODE model | bullet_sim |\n"
              "|---|---|---|\n", w, kRunS);
  row("yaw acceleration while the tyres slip (rad/s^2)", alpha, r.rate_at_10ms / 0.010);
  row("time to within 1 % of the command (s)", reach_s, r.first_s);
  row("yaw rate reached (rad/s)", w, r.rate_at_end);
  row("heading (rad)", w * kRunS - 2 * rampLossM(rim) / kSeparationM - spinSlipLossRad(rim),
      r.turn_rad);
  row("farthest base_footprint strays (m)", 0, r.farthest_m);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s <burger.urdf> <world.sdf> [linear_mps [angular_radps]]\n",
                 argv[0]);
    return 2;
  }
  const double v = argc > 3 ? std::atof(argv[3]) : 0.22, w = argc > 4 ? std::atof(argv[4]) : 2.84;
  try {
    const bullet_sim::RobotSpec robot = bullet_sim::parseRobotFile(argv[1]);
    const bullet_sim::WorldSpec world = bullet_sim::loadWorldFile(argv[2]);
    for (const bool turning : {false, true}) {
      Simulation sim(world, bullet_sim::SimConfig());
      sim.spawnRobot("burger", robot, bullet_sim::Pose3());
      drive(&sim, 0, 0, 1.0);  // settle
      if (turning) spin(&sim, w);
      else straight(&sim, v);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
