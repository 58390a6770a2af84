// The once-a-period status line: sim time, measured real-time factor, robot poses.
#pragma once

#include <bullet_sim/simulation.h>

#include <chrono>
#include <string>

namespace bullet_sim_node {

/// The status line: sim time, real-time factor, and each model's pose, with "TIPPED OVER"
/// (tilted beyond 45 degrees) or "STUCK IN A WALL" (more than 1 cm into a static body)
/// after a model in that state; `trouble` tells whether any is.
std::string statusLine(const bullet_sim::Simulation& sim, double real_time_factor, bool* trouble);

class StatusReporter {
 public:
  StatusReporter(const bullet_sim::Simulation& sim, double period_s);
  /// Logs the status line when a period of wall time has passed since the last one.
  void maybeReport();

 private:
  using Clock = std::chrono::steady_clock;
  const bullet_sim::Simulation& sim_;
  const std::chrono::duration<double> period_;
  Clock::time_point last_wall_;
  double last_sim_s_;
};

}  // namespace bullet_sim_node
