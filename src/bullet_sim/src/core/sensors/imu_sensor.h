#ifndef BULLET_SIM_CORE_IMU_SENSOR_H
#define BULLET_SIM_CORE_IMU_SENSOR_H

#include <random>

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// An IMU on a link. The linear acceleration is the change of the link's
/// velocity since the previous read (as Gazebo's IMU plugin differentiates
/// between its updates) minus gravity, so it reads +g upwards at rest.
class ImuSensor {
 public:
  ImuData read(const ImuSpec& spec, const Eigen::Isometry3d& T_world_link,
               const Eigen::Vector3d& linear_velocity, const Eigen::Vector3d& angular_velocity,
               const Eigen::Vector3d& gravity, double time_s, std::mt19937_64* rng);
  /// Forgets the previous read (after a reset or a teleport).
  void reset() { has_last_ = false; }

 private:
  bool has_last_ = false;
  double last_time_s_ = 0;
  Eigen::Vector3d last_velocity_{0, 0, 0};
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_IMU_SENSOR_H
