#ifndef BULLET_SIM_CORE_WRENCH_READINGS_H
#define BULLET_SIM_CORE_WRENCH_READINGS_H

#include <random>

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// A wrench in world axes with its torque taken about `point_world`.
struct WorldWrench {
  Eigen::Vector3d force_n{0, 0, 0};
  Eigen::Vector3d torque_nm{0, 0, 0};
  Eigen::Vector3d point_world{0, 0, 0};
};

/// libgazebo_ros_ft_sensor.so's reading (Gazebo's ODE joint GetForceTorque(0), body2):
/// `on_child` is what the joint exerts on its child; the reading is its opposite (what the
/// child exerts on the joint), its torque moved to the joint origin (the child link's
/// origin, as a URDF joint's frame is its child's), turned into the child link's axes:
/// force -R^T F, torque -R^T (tau + (p - o) x F) for rotation R and origin o of
/// T_world_child. Each of the six values gets Gaussian noise of sd gaussianNoise, drawn
/// in the order fx fy fz tx ty tz. frame_id: `child_link`.
WrenchData readForceTorque(const FtSensorSpec& spec, const WorldWrench& on_child,
                           const Eigen::Isometry3d& T_world_child,
                           const std::string& child_link, double time_s,
                           std::mt19937_64* rng);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_WRENCH_READINGS_H
