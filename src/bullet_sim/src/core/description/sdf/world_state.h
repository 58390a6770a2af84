#ifndef BULLET_SIM_CORE_WORLD_STATE_H
#define BULLET_SIM_CORE_WORLD_STATE_H

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "bullet_sim/types.h"

namespace bullet_sim {

/// One model of a world's saved <state>: world poses, as Gazebo writes them.
struct ModelState {
  std::optional<Pose3> pose;                ///< the model frame in the world
  std::map<std::string, Pose3> link_poses;  ///< by link name, in the world
  std::map<std::string, ModelState> models; ///< nested models, by name
};

/// The <state> of a world saved from Gazebo: where its models were when it was saved.
struct WorldState {
  std::map<std::string, ModelState> models;  ///< top-level models, by name
};

/// Reads the first <state> of a <world> element (Gazebo applies only the first one).
/// <insertions> and <deletions> are not applied: each adds a warning.
/// @throws LoadError naming the source, the model or link and the bad pose text.
WorldState readWorldState(const tinyxml2::XMLElement* world, const std::string& source,
                          std::vector<std::string>* warnings);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_WORLD_STATE_H
