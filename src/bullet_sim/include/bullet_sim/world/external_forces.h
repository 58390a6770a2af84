#ifndef BULLET_SIM_EXTERNAL_FORCES_H
#define BULLET_SIM_EXTERNAL_FORCES_H

#include <string>
#include <vector>

#include "bullet_sim/world/entity_frames.h"

namespace bullet_sim {

/// When an external force acts: from start_s for duration_s of sim time, or until it is
/// cleared when duration_s < 0. A start in the past means now (as Gazebo does).
struct ForceWindow {
  double start_s = 0;
  double duration_s = 0;
};

/// A wrench on one link (applied at its body's centre of mass, world axes).
struct BodyWrench {
  std::string robot, link;
  Wrench wrench;
  ForceWindow window;
};

/// An effort (torque, N m) on one joint.
struct JointEffort {
  std::string robot, joint;
  double effort = 0;
  ForceWindow window;
};

/// The bookkeeping of Gazebo's apply_body_wrench / apply_joint_effort: which wrenches and
/// efforts act at a physics step, and when they expire. Sim time is passed in.
///
/// A step that starts at time t applies every entry with start <= t < start + duration,
/// so a duration d acts for d / dt steps (impulse F d exactly); a duration of 0 acts for
/// exactly one step. Efforts and wrenches on the same joint or link add up.
class ExternalForces {
 public:
  void addWrench(BodyWrench wrench, double now_s);
  void addEffort(JointEffort effort, double now_s);

  /// Entries acting in the step that starts at `step_start_s`; entries that ended
  /// before it are dropped.
  std::vector<BodyWrench> wrenchesAt(double step_start_s);
  std::vector<JointEffort> effortsAt(double step_start_s);

  /// Removes the entries of one link / joint; returns how many were removed.
  size_t clearWrenches(const std::string& robot, const std::string& link);
  size_t clearEfforts(const std::string& robot, const std::string& joint);
  /// Removes every entry of a robot (it was deleted).
  void clearRobot(const std::string& robot);
  void clear();

  size_t wrenchCount() const { return wrenches_.size(); }
  size_t effortCount() const { return efforts_.size(); }

 private:
  std::vector<BodyWrench> wrenches_;
  std::vector<JointEffort> efforts_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_EXTERNAL_FORCES_H
