#ifndef BULLET_SIM_WORLD_MARKER_SET_H
#define BULLET_SIM_WORLD_MARKER_SET_H

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bullet_sim/render/world_markers.h"
#include "bullet_sim/simulation.h"

namespace bullet_sim {

/// Everything a viewer draws of a simulation's world: the static shapes, and the movable
/// models handed to track() at their current link poses. A latched topic keeps only its last
/// message, so update() hands out the whole set whenever a tracked model moved or vanished.
class WorldMarkerSet {
 public:
  /// @param position_tolerance_m, angle_tolerance_rad  smaller motions are not redrawn
  WorldMarkerSet(const WorldSpec& world, double position_tolerance_m = 0.001,
                 double angle_tolerance_rad = 0.002);

  /// Draws the model `name` (a robot of the simulation) with the world from now on.
  void track(const std::string& name);

  /// Draws every model of the simulation but `except`, those spawned later included, as
  /// Gazebo's window shows every model (a robot without a robot_state_publisher too).
  void trackEveryModelBut(std::set<std::string> except);

  /// The whole set (static shapes first) when it differs from what the last call returned
  /// (the first call always returns it); nothing when no tracked model moved. A tracked
  /// model the simulation no longer has is dropped.
  std::optional<std::vector<MarkerShape>> update(const Simulation& sim);

 private:
  std::vector<MarkerShape> static_markers_;
  std::set<std::string> tracked_;
  bool track_every_model_ = false;
  std::set<std::string> untracked_;  ///< when tracking every model: those left out
  MarkerChanges changes_;
  bool sent_ = false;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_WORLD_MARKER_SET_H
