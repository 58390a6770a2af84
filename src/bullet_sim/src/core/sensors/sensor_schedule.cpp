#include "sensors/sensor_schedule.h"

#include <cmath>

namespace bullet_sim {
namespace {

/// FNV-1a: a hash that is the same on every build, unlike std::hash.
uint64_t stableHash(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

std::mt19937_64 sensorRng(uint64_t seed, const std::string& robot, const std::string& sensor) {
  const uint64_t parts[3] = {seed, stableHash(robot), stableHash(sensor)};
  std::seed_seq seq{static_cast<uint32_t>(parts[0]), static_cast<uint32_t>(parts[0] >> 32),
                    static_cast<uint32_t>(parts[1]), static_cast<uint32_t>(parts[1] >> 32),
                    static_cast<uint32_t>(parts[2]), static_cast<uint32_t>(parts[2] >> 32)};
  return std::mt19937_64(seq);
}

bool periodElapsed(uint64_t k, double dt_s, double rate_hz) {
  if (rate_hz <= 0) return true;
  constexpr double kEps = 1e-9;  // absorbs rounding when the rate divides the step
  const double periods_now = static_cast<double>(k) * dt_s * rate_hz + kEps;
  const double periods_before = (static_cast<double>(k) - 1.0) * dt_s * rate_hz + kEps;
  return std::floor(periods_now) > std::floor(periods_before);
}

SensorSchedule::SensorSchedule(const std::string& robot, const RobotSpec& spec,
                               double joint_state_rate_hz)
    : robot_(robot) {
  for (size_t i = 0; i < spec.rays.size(); ++i) {
    entries_.push_back({SensorKind::Ray, i, spec.rays[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.imus.size(); ++i) {
    entries_.push_back({SensorKind::Imu, i, spec.imus[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.cameras.size(); ++i) {
    // A triggered camera is due when triggered only (Simulation::triggerCamera).
    if (!spec.cameras[i].trigger_topic.empty()) continue;
    entries_.push_back({SensorKind::Camera, i, spec.cameras[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.p3ds.size(); ++i) {
    entries_.push_back({SensorKind::GroundTruth, i, spec.p3ds[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.ranges.size(); ++i) {
    entries_.push_back({SensorKind::Range, i, spec.ranges[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.block_lasers.size(); ++i) {
    entries_.push_back({SensorKind::BlockLaser, i, spec.block_lasers[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.bumpers.size(); ++i) {
    entries_.push_back({SensorKind::Bumper, i, spec.bumpers[i].update_rate_hz});
  }
  for (size_t i = 0; i < spec.f3ds.size(); ++i) {
    entries_.push_back({SensorKind::F3d, i, 0.0});  // Gazebo's f3d has no rate: every step
  }
  for (size_t i = 0; i < spec.ft_sensors.size(); ++i) {
    entries_.push_back({SensorKind::ForceTorque, i, spec.ft_sensors[i].update_rate_hz});
  }
  if (spec.diff_drive) {
    drive_rate_hz_ = spec.diff_drive->update_rate_hz;
    entries_.push_back({SensorKind::Odometry, 0, drive_rate_hz_});
  }
  const std::optional<PlanarMoveSpec>& planar = spec.planar_move;
  if (planar && planar->odometry_rate_hz > 0) {  // rate 0: the plugin publishes none
    entries_.push_back({SensorKind::PlanarMoveOdometry, 0, planar->odometry_rate_hz});
  }
  for (size_t i = 0; i < spec.joint_state_publishers.size(); ++i) {
    entries_.push_back(
        {SensorKind::PluginJointStates, i, spec.joint_state_publishers[i].update_rate_hz});
  }
  // A joint state publisher plugin takes the place of the joint states of every joint.
  if (spec.joint_state_publishers.empty()) {
    entries_.push_back({SensorKind::JointStates, 0, joint_state_rate_hz});
  }
}

bool SensorSchedule::Entry::due(uint64_t k, double dt_s) const {
  return k > origin && periodElapsed(k - origin, dt_s, rate_hz);
}

void SensorSchedule::collectDue(uint64_t k, double dt_s, std::vector<DueSensor>* due) const {
  for (const Entry& e : entries_) {
    if (e.due(k, dt_s)) due->push_back({robot_, e.kind, e.index});
  }
}

bool SensorSchedule::anyDue(uint64_t k, double dt_s) const {
  for (const Entry& e : entries_) {
    if (e.due(k, dt_s)) return true;
  }
  return false;
}

void SensorSchedule::startAfter(uint64_t spawn_step, double dt_s) {
  for (Entry& e : entries_) {
    // Gazebo's sensors (not the model plugins: IMU, odometry, joint states).
    if (e.kind == SensorKind::Imu || e.kind == SensorKind::Odometry ||
        e.kind == SensorKind::JointStates || e.kind == SensorKind::PlanarMoveOdometry ||
        e.kind == SensorKind::PluginJointStates) {
      continue;
    }
    if (e.rate_hz <= 0) continue;  // every step anyway
    // The first step whose period ends, counted from step 0.
    uint64_t first = 1;
    while (!periodElapsed(first, dt_s, e.rate_hz)) ++first;
    e.origin = spawn_step + 1 > first ? spawn_step + 1 - first : 0;
  }
}

void SensorSchedule::restart() {
  for (Entry& e : entries_) e.origin = 0;
}

}  // namespace bullet_sim
