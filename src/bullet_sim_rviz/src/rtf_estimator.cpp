#include "bullet_sim_rviz/rtf_estimator.h"

#include <stdexcept>

namespace bullet_sim_rviz {

RtfEstimator::RtfEstimator(double window_s) : window_s_(window_s) {
  if (!(window_s > 0)) throw std::invalid_argument("RtfEstimator: window must be > 0 s");
}

void RtfEstimator::addSample(double wall_s, double sim_s) {
  if (!samples_.empty() && sim_s < samples_.back().second) samples_.clear();
  if (samples_.empty() || sim_s > samples_.back().second) last_advance_wall_s_ = wall_s;
  samples_.emplace_back(wall_s, sim_s);
  // Keep one sample at or before the window's start so the span covers the whole window.
  while (samples_.size() > 2 && samples_[1].first <= wall_s - window_s_) samples_.pop_front();
}

std::optional<double> RtfEstimator::factor(double now_wall_s) const {
  if (samples_.size() < 2 || now_wall_s - samples_.back().first > window_s_) return std::nullopt;
  const double wall_span = samples_.back().first - samples_.front().first;
  if (wall_span < 0.25 * window_s_) return std::nullopt;
  return (samples_.back().second - samples_.front().second) / wall_span;
}

bool RtfEstimator::stalled(double now_wall_s, double still_s) const {
  return !samples_.empty() && now_wall_s - samples_.back().first <= window_s_ &&
         now_wall_s - last_advance_wall_s_ >= still_s;
}

}  // namespace bullet_sim_rviz
