// The once-a-period status line: sim time, measured real-time factor, robot poses.
#pragma once

#include <bullet_sim/simulation.h>

#include <chrono>

namespace bullet_sim_node {

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
