#include "runner/status_reporter.h"

#include <ros/console.h>

#include <cmath>
#include <sstream>

namespace bullet_sim_node {
namespace {

double yawRad(const Eigen::Quaterniond& q) {
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                    1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
}

/// A value as printed with 3 decimals, without a "-0.000" for a tiny negative one.
double shown(double value) { return std::fabs(value) < 0.0005 ? 0.0 : value; }

}  // namespace

std::string statusLine(const bullet_sim::Simulation& sim, double real_time_factor,
                       bool* trouble) {
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(3);
  line << "sim time " << sim.timeS() << " s, real-time factor ";
  line.precision(2);
  line << real_time_factor;
  *trouble = false;
  for (const std::string& robot : sim.robotNames()) {
    const bullet_sim::Pose3 pose = sim.modelPose(robot);
    line.precision(3);
    line << ", " << robot << " at x " << shown(pose.position.x()) << " y "
         << shown(pose.position.y()) << " yaw " << shown(yawRad(pose.orientation));
    const bullet_sim::ModelCondition condition = sim.condition(robot);
    if (condition.tippedOver()) {
      line.precision(0);
      line << " TIPPED OVER (tilted " << condition.tilt_rad * 180.0 / M_PI << " deg)";
      *trouble = true;
    }
    if (condition.inWall()) {
      line.precision(3);
      line << " STUCK IN A WALL (" << condition.wall_penetration_m << " m deep)";
      *trouble = true;
    }
  }
  return line.str();
}

StatusReporter::StatusReporter(const bullet_sim::Simulation& sim, double period_s)
    : sim_(sim), period_(period_s), last_wall_(Clock::now()), last_sim_s_(sim.timeS()) {}

void StatusReporter::maybeReport() {
  const Clock::time_point now = Clock::now();
  const std::chrono::duration<double> wall_elapsed = now - last_wall_;
  if (wall_elapsed < period_) return;
  const double sim_s = sim_.timeS();
  // After a reset sim time restarted from 0 within this period.
  const double sim_advanced_s = sim_s >= last_sim_s_ ? sim_s - last_sim_s_ : sim_s;
  const double factor = sim_advanced_s / wall_elapsed.count();
  bool trouble = false;
  const std::string line = statusLine(sim_, factor, &trouble);
  if (trouble) {
    ROS_WARN_STREAM(line);
  } else {
    ROS_INFO_STREAM(line);
  }
  last_wall_ = now;
  last_sim_s_ = sim_s;
}

}  // namespace bullet_sim_node
