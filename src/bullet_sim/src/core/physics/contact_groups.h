#ifndef BULLET_SIM_CORE_CONTACT_GROUPS_H
#define BULLET_SIM_CORE_CONTACT_GROUPS_H

#include <vector>

#include <btBulletCollisionCommon.h>

namespace bullet_sim {

/// Two robots whose boxes, each grown by this (plus what their speeds cover in the steps
/// to come), overlap may touch in those steps and are simulated in one world.
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

/// For each member, the group it is simulated in during the coming steps, `horizon_s` of
/// sim time in all (twice the speeds it covers allow for a speed that grows): the
/// smallest id among the robots it may touch, directly or through others (robots whose
/// grown boxes overlap, see kJoinMarginM and kKeepMarginM). The result depends on the
/// members and their order only.
std::vector<int> contactGroups(const std::vector<GroupMember>& members, double horizon_s);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_CONTACT_GROUPS_H
