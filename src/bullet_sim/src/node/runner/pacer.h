// Keeps sim time and wall time in a set ratio by sleeping.
#pragma once

#include <chrono>

namespace bullet_sim_node {

/// Sleeps so that sim time advances `real_time_factor` times as fast as the wall clock
/// (0: never sleeps). Re-anchors itself whenever sim time goes backwards (a reset);
/// call restart() after a pause so the paused time is not caught up.
class Pacer {
 public:
  explicit Pacer(double real_time_factor);
  void restart(double sim_time_s);
  /// Paces at a new factor from `sim_time_s` on (set_physics_properties).
  void setRealTimeFactor(double real_time_factor, double sim_time_s);
  double realTimeFactor() const { return real_time_factor_; }
  /// Returns when the wall clock has reached the moment that matches `sim_time_s`.
  void waitUntil(double sim_time_s);

 private:
  using Clock = std::chrono::steady_clock;
  double real_time_factor_;
  Clock::time_point anchor_wall_;
  double anchor_sim_s_ = 0;
  double last_sim_s_ = 0;
};

}  // namespace bullet_sim_node
