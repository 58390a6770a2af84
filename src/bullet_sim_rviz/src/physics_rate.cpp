#include "bullet_sim_rviz/physics_rate.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace bullet_sim_rviz {
namespace {

void check(bool ok, const std::string& what, double value, const std::string& rule) {
  if (!ok) throw std::invalid_argument(what + " " + std::to_string(value) + " " + rule);
}

}  // namespace

double maxUpdateRateFor(double factor, double time_step_s) {
  check(std::isfinite(factor) && factor >= 0, "real-time factor", factor,
        "must be >= 0 (0 = as fast as possible)");
  check(std::isfinite(time_step_s) && time_step_s > 0, "time_step", time_step_s,
        "must be > 0 s");
  return factor / time_step_s;
}

double realTimeFactorOf(double max_update_rate_hz, double time_step_s) {
  check(std::isfinite(max_update_rate_hz) && max_update_rate_hz >= 0, "max_update_rate",
        max_update_rate_hz, "must be >= 0 Hz");
  check(std::isfinite(time_step_s) && time_step_s > 0, "time_step", time_step_s,
        "must be > 0 s");
  return max_update_rate_hz * time_step_s;
}

}  // namespace bullet_sim_rviz
