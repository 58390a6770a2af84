// Keeps sim time and wall time in a set ratio by sleeping.
#pragma once

#include <chrono>
#include <functional>

namespace bullet_sim_node {

/// Sleeps so that sim time advances `real_time_factor` times as fast as the wall clock
/// (0: never sleeps). Re-anchors itself whenever sim time goes backwards (a reset);
/// call restart() after a pause so the paused time is not caught up.
///
/// Wall time lost to a stall (a slow render, a spawn, a descheduled process) is not made
/// up: when a step ends more than kMaxLagS of wall time after the moment its sim time
/// matches, pacing starts again from that step and that moment, as Gazebo's world waits
/// for each step from the wall time of the previous one. A smaller lag (a sleep that
/// woke late) is caught up, so the factor holds over long runs.
class Pacer {
 public:
  using Clock = std::chrono::steady_clock;
  /// The lag behind the wall clock that is still caught up (wall seconds).
  static constexpr double kMaxLagS = 0.01;

  explicit Pacer(double real_time_factor);
  /// With its own clock and sleep (tests): `now` reads the wall clock, `sleep_until`
  /// returns when `now` has reached its argument.
  Pacer(double real_time_factor, std::function<Clock::time_point()> now,
        std::function<void(Clock::time_point)> sleep_until);
  void restart(double sim_time_s);
  /// Paces at a new factor from `sim_time_s` on (set_physics_properties).
  void setRealTimeFactor(double real_time_factor, double sim_time_s);
  double realTimeFactor() const { return real_time_factor_; }
  /// Returns when the wall clock has reached the moment that matches `sim_time_s`; when
  /// that moment is more than kMaxLagS past, at once, pacing on from now.
  void waitUntil(double sim_time_s);
  /// How many steps of `step_s` to take at once from `sim_time_s`: 1 while the simulation
  /// keeps up with the wall clock (a step, then a wait, as Gazebo paces its world), as many
  /// as sim time is behind it when it does not, and `max_steps` when nothing paces it (a
  /// real-time factor of 0). Between 1 and max_steps (>= 1).
  unsigned stepsDue(double sim_time_s, double step_s, unsigned max_steps) const;

 private:
  double real_time_factor_;
  std::function<Clock::time_point()> now_;
  std::function<void(Clock::time_point)> sleep_until_;
  Clock::time_point anchor_wall_;
  double anchor_sim_s_ = 0;
  double last_sim_s_ = 0;
};

}  // namespace bullet_sim_node
