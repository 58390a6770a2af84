#ifndef BULLET_SIM_CORE_CONTACT_GROUPS_H
#define BULLET_SIM_CORE_CONTACT_GROUPS_H

#include <vector>

#include <btBulletCollisionCommon.h>

namespace bullet_sim {

/// Two robots whose boxes, each grown by this (plus what their speeds cover in a step),
/// overlap may touch in the coming step and are simulated in one world.
constexpr double kJoinMarginM = 0.05;
/// Robots already in one world stay there until their boxes are this far apart, so that
/// two robots driving side by side do not move between worlds every step.
constexpr double kKeepMarginM = 0.10;

/// Where a robot is and what group (world) it is in before the coming step.
struct GroupMember {
  int id;
  bool collides;  ///< false: no colliding body, it touches nothing (a box and speed unused)
  btVector3 aabb_min, aabb_max;
  double speed_mps;  ///< the largest speed of any point of it
  int group;         ///< the id of the robot whose world it is in now
};

/// For each member, the group it is simulated in during the coming step of dt_s: the
/// smallest id among the robots it may touch, directly or through others (robots whose
/// grown boxes overlap, see kJoinMarginM and kKeepMarginM). The result depends on the
/// members and their order only.
std::vector<int> contactGroups(const std::vector<GroupMember>& members, double dt_s);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_CONTACT_GROUPS_H
