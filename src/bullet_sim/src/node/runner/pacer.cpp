#include "runner/pacer.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <utility>

namespace bullet_sim_node {

Pacer::Pacer(double real_time_factor)
    : Pacer(real_time_factor, [] { return Clock::now(); },
            [](Clock::time_point t) { std::this_thread::sleep_until(t); }) {}

Pacer::Pacer(double real_time_factor, std::function<Clock::time_point()> now,
             std::function<void(Clock::time_point)> sleep_until)
    : real_time_factor_(real_time_factor),
      now_(std::move(now)),
      sleep_until_(std::move(sleep_until)) {
  restart(0);
}

void Pacer::restart(double sim_time_s) {
  anchor_wall_ = now_();
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
  const Clock::time_point now = now_();
  if (target > now) {
    sleep_until_(target);
  } else if (std::chrono::duration<double>(now - target).count() > kMaxLagS) {
    restart(sim_time_s);  // a stall: paced on from here, not caught up
  }
}

unsigned Pacer::stepsDue(double sim_time_s, double step_s, unsigned max_steps) const {
  max_steps = std::max(max_steps, 1u);
  if (real_time_factor_ <= 0) return max_steps;
  if (sim_time_s < last_sim_s_) return 1;  // a reset: waitUntil() anchors anew
  const double wall_s = std::chrono::duration<double>(now_() - anchor_wall_).count();
  // The wall time the steps since the anchor should have taken, and how far the wall clock
  // is past it: a lag beyond kMaxLagS is not caught up (waitUntil re-anchors).
  const double paced_s = (sim_time_s - anchor_sim_s_) / real_time_factor_;
  const double lag_s = std::min(wall_s - paced_s, kMaxLagS);
  const double behind = std::floor(lag_s * real_time_factor_ / step_s);
  if (!(behind >= 1)) return 1;  // keeping up
  return behind >= max_steps ? max_steps : static_cast<unsigned>(behind);
}

}  // namespace bullet_sim_node
