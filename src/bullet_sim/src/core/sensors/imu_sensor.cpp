#include "sensors/imu_sensor.h"

namespace bullet_sim {

ImuData ImuSensor::read(const ImuSpec& spec, const Eigen::Isometry3d& T_world_link,
                        const Eigen::Vector3d& linear_velocity,
                        const Eigen::Vector3d& angular_velocity, const Eigen::Vector3d& gravity,
                        double time_s, std::mt19937_64* rng) {
  Eigen::Vector3d accel_world = Eigen::Vector3d::Zero();
  if (has_last_ && time_s > last_time_s_) {
    accel_world = (linear_velocity - last_velocity_) / (time_s - last_time_s_);
  }
  has_last_ = true;
  last_time_s_ = time_s;
  last_velocity_ = linear_velocity;

  const Eigen::Matrix3d R_link_world = T_world_link.linear().transpose();
  ImuData d;
  d.time_s = time_s;
  d.frame_id = spec.frame_id;
  d.orientation = Eigen::Quaterniond(T_world_link.linear()).normalized();
  d.angular_velocity = R_link_world * angular_velocity;
  d.linear_acceleration = R_link_world * (accel_world - gravity);
  if (spec.gaussian_noise > 0) {
    std::normal_distribution<double> noise(0.0, spec.gaussian_noise);
    for (int i = 0; i < 3; ++i) {
      d.angular_velocity[i] += noise(*rng);
      d.linear_acceleration[i] += noise(*rng);
    }
  }
  const double variance = spec.gaussian_noise * spec.gaussian_noise;
  d.orientation_cov = variance;
  d.angular_velocity_cov = variance;
  d.linear_acceleration_cov = variance;
  return d;
}

}  // namespace bullet_sim
