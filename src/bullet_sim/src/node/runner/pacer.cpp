#include "runner/pacer.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace bullet_sim_node {

Pacer::Pacer(double real_time_factor) : real_time_factor_(real_time_factor) { restart(0); }

void Pacer::restart(double sim_time_s) {
  anchor_wall_ = Clock::now();
  anchor_sim_s_ = sim_time_s;
  last_sim_s_ = sim_time_s;
}

void Pacer::setRealTimeFactor(double real_time_factor, double sim_time_s) {
  real_time_factor_ = real_time_factor;
  restart(sim_time_s);
}

void Pacer::waitUntil(double sim_time_s) {
  if (real_time_factor_ <= 0) return;
  if (sim_time_s < last_sim_s_) restart(sim_time_s);
  last_sim_s_ = sim_time_s;
  const std::chrono::duration<double> wall_offset((sim_time_s - anchor_sim_s_) /
                                                  real_time_factor_);
  const Clock::time_point target =
      anchor_wall_ + std::chrono::duration_cast<Clock::duration>(wall_offset);
  if (target > Clock::now()) std::this_thread::sleep_until(target);
}

unsigned Pacer::stepsDue(double sim_time_s, double step_s, unsigned max_steps) const {
  max_steps = std::max(max_steps, 1u);
  if (real_time_factor_ <= 0) return max_steps;
  if (sim_time_s < last_sim_s_) return 1;  // a reset: waitUntil() anchors anew
  const double wall_s = std::chrono::duration<double>(Clock::now() - anchor_wall_).count();
  const double allowed_s = anchor_sim_s_ + wall_s * real_time_factor_;
  const double behind = std::floor((allowed_s - sim_time_s) / step_s);
  if (!(behind >= 1)) return 1;  // keeping up
  return behind >= max_steps ? max_steps : static_cast<unsigned>(behind);
}

}  // namespace bullet_sim_node
