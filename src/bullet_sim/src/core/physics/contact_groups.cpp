#include "physics/contact_groups.h"

#include <algorithm>
#include <numeric>

namespace bullet_sim {
namespace {

bool mayTouch(const GroupMember& a, const GroupMember& b, double horizon_s) {
  if (!a.collides || !b.collides) return false;
  const double margin = (a.group == b.group ? kKeepMarginM : kJoinMarginM) +
                        2.0 * (a.speed_mps + b.speed_mps) * horizon_s;
  for (int axis = 0; axis < 3; ++axis) {
    if (a.aabb_min[axis] - margin > b.aabb_max[axis] ||
        b.aabb_min[axis] - margin > a.aabb_max[axis]) {
      return false;
    }
  }
  return true;
}

int root(std::vector<size_t>& parent, size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return static_cast<int>(i);
}

}  // namespace

std::vector<int> contactGroups(const std::vector<GroupMember>& members, double horizon_s) {
  std::vector<size_t> parent(members.size());
  std::iota(parent.begin(), parent.end(), size_t{0});
  for (size_t i = 0; i < members.size(); ++i) {
    for (size_t j = i + 1; j < members.size(); ++j) {
      if (!mayTouch(members[i], members[j], horizon_s)) continue;
      const int ri = root(parent, i), rj = root(parent, j);
      if (ri != rj) parent[std::max(ri, rj)] = static_cast<size_t>(std::min(ri, rj));
    }
  }
  std::vector<int> smallest(members.size(), 0);
  for (size_t i = 0; i < members.size(); ++i) smallest[i] = members[i].id;
  for (size_t i = 0; i < members.size(); ++i) {
    const int r = root(parent, i);
    smallest[r] = std::min(smallest[r], members[i].id);
  }
  std::vector<int> groups(members.size());
  for (size_t i = 0; i < members.size(); ++i) groups[i] = smallest[root(parent, i)];
  return groups;
}

}  // namespace bullet_sim
