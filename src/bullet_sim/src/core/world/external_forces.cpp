#include "bullet_sim/world/external_forces.h"

#include <algorithm>

namespace bullet_sim {
namespace {

/// Absorbs the rounding of sim time (a sum of steps) against start + duration.
constexpr double kTimeEpsS = 1e-9;

ForceWindow startingNoEarlierThan(ForceWindow window, double now_s) {
  window.start_s = std::max(window.start_s, now_s);
  return window;
}

bool started(const ForceWindow& w, double t) { return t >= w.start_s - kTimeEpsS; }

/// True once the window has no step left to act in.
bool ended(const ForceWindow& w, double t) {
  if (w.duration_s < 0) return false;
  const bool one_step_done = t > w.start_s + kTimeEpsS;
  return one_step_done && t >= w.start_s + w.duration_s - kTimeEpsS;
}

template <typename Entry>
std::vector<Entry> activeAt(std::vector<Entry>* entries, double t) {
  entries->erase(std::remove_if(entries->begin(), entries->end(),
                                [t](const Entry& e) { return ended(e.window, t); }),
                 entries->end());
  std::vector<Entry> active;
  for (const Entry& e : *entries) {
    if (started(e.window, t)) active.push_back(e);
  }
  return active;
}

template <typename Entry, typename Match>
size_t removeIf(std::vector<Entry>* entries, Match match) {
  const size_t before = entries->size();
  entries->erase(std::remove_if(entries->begin(), entries->end(), match), entries->end());
  return before - entries->size();
}

}  // namespace

void ExternalForces::addWrench(BodyWrench wrench, double now_s) {
  wrench.window = startingNoEarlierThan(wrench.window, now_s);
  wrenches_.push_back(std::move(wrench));
}

void ExternalForces::addEffort(JointEffort effort, double now_s) {
  effort.window = startingNoEarlierThan(effort.window, now_s);
  efforts_.push_back(std::move(effort));
}

std::vector<BodyWrench> ExternalForces::wrenchesAt(double step_start_s) {
  return activeAt(&wrenches_, step_start_s);
}

std::vector<JointEffort> ExternalForces::effortsAt(double step_start_s) {
  return activeAt(&efforts_, step_start_s);
}

size_t ExternalForces::clearWrenches(const std::string& robot, const std::string& link) {
  return removeIf(&wrenches_,
                  [&](const BodyWrench& w) { return w.robot == robot && w.link == link; });
}

size_t ExternalForces::clearEfforts(const std::string& robot, const std::string& joint) {
  return removeIf(&efforts_,
                  [&](const JointEffort& e) { return e.robot == robot && e.joint == joint; });
}

void ExternalForces::clearRobot(const std::string& robot) {
  removeIf(&wrenches_, [&](const BodyWrench& w) { return w.robot == robot; });
  removeIf(&efforts_, [&](const JointEffort& e) { return e.robot == robot; });
}

void ExternalForces::clear() {
  wrenches_.clear();
  efforts_.clear();
}

}  // namespace bullet_sim
