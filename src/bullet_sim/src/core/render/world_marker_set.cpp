#include "bullet_sim/render/world_marker_set.h"

#include <algorithm>

namespace bullet_sim {

WorldMarkerSet::WorldMarkerSet(const WorldSpec& world, double position_tolerance_m,
                               double angle_tolerance_rad)
    : static_markers_(worldShapeMarkers(world)),
      changes_(position_tolerance_m, angle_tolerance_rad) {}

void WorldMarkerSet::track(const std::string& name) {
  tracked_.insert(name);
  sent_ = false;
}

void WorldMarkerSet::trackEveryModelBut(std::set<std::string> except) {
  track_every_model_ = true;
  untracked_ = std::move(except);
  sent_ = false;
}

std::optional<std::vector<MarkerShape>> WorldMarkerSet::update(const Simulation& sim) {
  const std::vector<std::string> models = sim.robotNames();
  bool changed = !sent_;
  if (track_every_model_) {
    for (const std::string& name : models) {
      if (!untracked_.count(name)) changed |= tracked_.insert(name).second;
    }
  }
  for (auto it = tracked_.begin(); it != tracked_.end();) {
    const bool gone = std::find(models.begin(), models.end(), *it) == models.end();
    changed |= gone;
    it = gone ? tracked_.erase(it) : std::next(it);
  }
  std::vector<MarkerShape> moving;
  for (const std::string& name : tracked_) {
    const auto markers = modelMarkers(name, sim.robotSpec(name), sim.linkPoses(name));
    moving.insert(moving.end(), markers.begin(), markers.end());
  }
  changed |= !changes_.update(moving).empty();
  if (!changed) return std::nullopt;
  sent_ = true;
  std::vector<MarkerShape> all = static_markers_;
  all.insert(all.end(), moving.begin(), moving.end());
  return all;
}

}  // namespace bullet_sim
