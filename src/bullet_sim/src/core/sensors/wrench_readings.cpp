#include "sensors/wrench_readings.h"

namespace bullet_sim {

WrenchData readForceTorque(const FtSensorSpec& spec, const WorldWrench& on_child,
                           const Eigen::Isometry3d& T_world_child,
                           const std::string& child_link, double time_s,
                           std::mt19937_64* rng) {
  const Eigen::Matrix3d R_world_child = T_world_child.linear();
  const Eigen::Vector3d arm = on_child.point_world - T_world_child.translation();
  const Eigen::Vector3d torque_at_joint = on_child.torque_nm + arm.cross(on_child.force_n);
  WrenchData reading;
  reading.time_s = time_s;
  reading.frame_id = child_link;
  reading.force_n = -(R_world_child.transpose() * on_child.force_n);
  reading.torque_nm = -(R_world_child.transpose() * torque_at_joint);
  if (spec.gaussian_noise > 0) {
    std::normal_distribution<double> noise(0.0, spec.gaussian_noise);
    for (int i = 0; i < 3; ++i) reading.force_n[i] += noise(*rng);
    for (int i = 0; i < 3; ++i) reading.torque_nm[i] += noise(*rng);
  }
  return reading;
}

}  // namespace bullet_sim
