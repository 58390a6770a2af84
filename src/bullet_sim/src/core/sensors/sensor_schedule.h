#ifndef BULLET_SIM_CORE_SENSOR_SCHEDULE_H
#define BULLET_SIM_CORE_SENSOR_SCHEDULE_H

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// Joint states of a robot without a diff drive are due at this rate.
constexpr double kDefaultJointStateRateHz = 30.0;

/// The noise generator of one sensor, seeded from (seed, robot, sensor) only,
/// so that it does not depend on spawn order or on other sensors' reads.
std::mt19937_64 sensorRng(uint64_t seed, const std::string& robot, const std::string& sensor);

/// True when a period of `rate_hz` ends within step k (of length dt_s):
/// rates that do not divide the step are met on average. rate <= 0: every step.
bool periodElapsed(uint64_t k, double dt_s, double rate_hz);

/// Which sensors of one robot are due at a physics step.
class SensorSchedule {
 public:
  SensorSchedule() = default;
  SensorSchedule(const std::string& robot, const RobotSpec& spec, double joint_state_rate_hz);

  /// The diff drive's motors update at the start of step k (first at k = 1).
  bool driveDue(uint64_t k, double dt_s) const {
    return periodElapsed(k - 1, dt_s, drive_rate_hz_);
  }
  /// Appends the sensors whose period ended with step k.
  void collectDue(uint64_t k, double dt_s, std::vector<DueSensor>* due) const;
  /// Whether collectDue(k, dt_s, ...) would append anything.
  bool anyDue(uint64_t k, double dt_s) const;

  /// A robot spawned after world step `spawn_step` (the steps already taken): its rays,
  /// cameras, range sensors, block lasers and bumpers measure first with the next step when the world has run one of their periods
  /// by then, as Gazebo's sensors do (their last update counts from world time 0), and
  /// every period after that. Sensors of a robot spawned earlier keep world-time phase.
  void startAfter(uint64_t spawn_step, double dt_s);
  /// World time starts again (a world reset): every period counts from step 0.
  void restart();

 private:
  struct Entry {
    SensorKind kind;
    size_t index;
    double rate_hz;
    uint64_t origin = 0;  ///< the step its periods count from
    bool due(uint64_t k, double dt_s) const;  ///< its period ends with step k
  };
  std::string robot_;
  std::vector<Entry> entries_;
  double drive_rate_hz_ = 0;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SENSOR_SCHEDULE_H
