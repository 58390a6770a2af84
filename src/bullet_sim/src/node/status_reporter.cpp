#include "status_reporter.h"

#include <ros/console.h>

#include <cmath>
#include <sstream>

namespace bullet_sim_node {
namespace {

double yawRad(const Eigen::Quaterniond& q) {
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                    1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
}

}  // namespace

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
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(3);
  line << "sim time " << sim_s << " s, real-time factor ";
  line.precision(2);
  line << factor;
  line.precision(3);
  for (const std::string& robot : sim_.robotNames()) {
    const bullet_sim::Pose3 pose = sim_.modelPose(robot);
    line << ", " << robot << " at x " << pose.position.x() << " y " << pose.position.y()
         << " yaw " << yawRad(pose.orientation);
  }
  ROS_INFO_STREAM(line.str());
  last_wall_ = now;
  last_sim_s_ = sim_s;
}

}  // namespace bullet_sim_node
