#ifndef BULLET_SIM_RVIZ_RTF_ESTIMATOR_H
#define BULLET_SIM_RVIZ_RTF_ESTIMATOR_H

#include <deque>
#include <optional>
#include <utility>

namespace bullet_sim_rviz {

/// Measures the real-time factor from /clock: how much sim time passed per second of wall
/// time over a sliding window. Times are passed in (seconds), nothing reads a clock.
class RtfEstimator {
 public:
  /// @param window_s  wall seconds of samples the estimate spans
  /// @throws std::invalid_argument unless window_s > 0
  explicit RtfEstimator(double window_s = 2.0);

  /// One /clock message: sim time `sim_s` received at wall time `wall_s`. A sim time that
  /// goes backwards (a reset) starts the measurement again.
  void addSample(double wall_s, double sim_s);

  /// The factor at wall time `now_wall_s`, or nothing while fewer than a quarter window of
  /// samples exist or when the newest sample is older than the window (no /clock any more).
  std::optional<double> factor(double now_wall_s) const;

  /// True when /clock still arrives (within the window) but its time has not moved for
  /// `still_s` wall seconds: a paused simulator.
  bool stalled(double now_wall_s, double still_s) const;

  void clear() { samples_.clear(); }

 private:
  double window_s_;
  std::deque<std::pair<double, double>> samples_;  ///< (wall_s, sim_s), oldest first
  double last_advance_wall_s_ = 0;  ///< when the sim time last moved forward
};

}  // namespace bullet_sim_rviz

#endif  // BULLET_SIM_RVIZ_RTF_ESTIMATOR_H
