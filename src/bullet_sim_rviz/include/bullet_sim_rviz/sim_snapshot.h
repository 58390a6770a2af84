#ifndef BULLET_SIM_RVIZ_SIM_SNAPSHOT_H
#define BULLET_SIM_RVIZ_SIM_SNAPSHOT_H

#include <optional>
#include <string>
#include <vector>

namespace bullet_sim_rviz {

/// What the simulation panel knows of the simulator at one moment.
struct SimSnapshot {
  bool services_available = false;  ///< /gazebo/pause_physics is advertised
  std::optional<double> sim_time_s;  ///< the newest /clock
  std::optional<double> measured_rtf;  ///< from /clock against wall time
  bool clock_stalled = false;          ///< /clock arrives but its time stands still
  std::optional<bool> paused;          ///< from get_physics_properties, when it is served
  std::optional<double> target_rtf;    ///< max_update_rate * time_step, when served
  std::vector<std::string> models;     ///< get_world_properties' model_names
};

/// The panel's headline: no simulator, waiting for /clock, running or paused. When
/// get_physics_properties is not served, a stalled clock counts as paused.
std::string headline(const SimSnapshot& s);
/// True when the simulation is known or measured to be paused.
bool isPaused(const SimSnapshot& s);
/// "12.345 s", or "-" before the first /clock.
std::string simTimeText(const std::optional<double>& sim_time_s);
/// "0.98" (two significant decimals below 10, fewer above), or "-" while unknown.
std::string rtfText(const std::optional<double>& rtf);

}  // namespace bullet_sim_rviz

#endif  // BULLET_SIM_RVIZ_SIM_SNAPSHOT_H
