#include "bullet_sim_rviz/sim_snapshot.h"

#include <cmath>
#include <cstdio>

namespace bullet_sim_rviz {

bool isPaused(const SimSnapshot& s) {
  if (s.paused) return *s.paused;
  return s.clock_stalled;
}

std::string headline(const SimSnapshot& s) {
  if (!s.services_available)
    return "No simulator running (no /gazebo/pause_physics service)";
  if (!s.sim_time_s) return "Simulator found, waiting for /clock";
  return isPaused(s) ? "Simulation paused" : "Simulation running";
}

std::string simTimeText(const std::optional<double>& sim_time_s) {
  if (!sim_time_s) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f s", *sim_time_s);
  return text;
}

std::string rtfText(const std::optional<double>& rtf) {
  if (!rtf) return "-";
  char text[32];
  std::snprintf(text, sizeof text, std::fabs(*rtf) < 10 ? "%.2f" : "%.0f", *rtf);
  return text;
}

}  // namespace bullet_sim_rviz
