#ifndef BULLET_SIM_ENTITY_FRAMES_H
#define BULLET_SIM_ENTITY_FRAMES_H

#include <optional>
#include <string>

#include "bullet_sim/types.h"

namespace bullet_sim {

/// Pose and twist of an entity (a model's root link or one link) in the world frame;
/// the twist is the velocity of the entity's origin.
struct EntityState {
  Pose3 pose;
  Twist3 twist;
};

/// A model or one of its links, named as Gazebo names them: "model" or "model::link".
struct EntityName {
  std::string model;
  std::string link;  ///< empty for the model itself
};

/// Splits an entity name against the known model names: "model" or "model::link" for a
/// model in `models`. "" and "world" are not entities (the world frame): std::nullopt, as
/// for unknown names. Whether the link exists is for the caller to check.
template <typename Models>
std::optional<EntityName> splitEntityName(const std::string& name, const Models& models) {
  for (const std::string& model : models) {
    if (name == model) return EntityName{model, ""};
    if (name.size() > model.size() + 2 && name.compare(0, model.size(), model) == 0 &&
        name.compare(model.size(), 2, "::") == 0) {
      return EntityName{model, name.substr(model.size() + 2)};
    }
  }
  return std::nullopt;
}

/// True for the names that mean the world frame: "" and "world".
bool isWorldFrameName(const std::string& name);

/// `entity` expressed in `frame`, as Gazebo's get_model_state / get_link_state give it:
/// the pose relative to the frame's pose, and the velocity difference rotated into the
/// frame's axes (linear: v - v_frame, angular: w - w_frame).
EntityState expressIn(const EntityState& entity, const EntityState& frame);

/// The world state of an entity given relative to `frame`, as Gazebo's set_model_state
/// takes it: pose = frame pose * relative pose; the twist's vectors are rotated from the
/// frame's axes into the world's (the frame's own motion is not added).
EntityState stateInWorld(const EntityState& relative, const Pose3& frame);

/// A force and torque acting on a body at its centre of mass, in world axes.
struct Wrench {
  Eigen::Vector3d force_n{0, 0, 0};
  Eigen::Vector3d torque_nm{0, 0, 0};
};

/// Gazebo's apply_body_wrench: `force` and `torque` are given in the axes of a frame with
/// orientation `frame_orientation`, the force acting at `reference_point` (an offset from
/// the body's centre of mass, in the same axes). Returns the equivalent wrench at the
/// centre of mass in world axes: torque + reference_point x force, rotated.
Wrench wrenchInWorld(const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
                     const Eigen::Vector3d& reference_point,
                     const Eigen::Quaterniond& frame_orientation);

/// True when every component of the pose is finite (a zero quaternion is usable: it
/// means no rotation, as Gazebo reads it).
bool isUsablePose(const Pose3& pose);
bool isFiniteTwist(const Twist3& twist);

}  // namespace bullet_sim

#endif  // BULLET_SIM_ENTITY_FRAMES_H
