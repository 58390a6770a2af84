#ifndef BULLET_SIM_CORE_RAY_CONE_H
#define BULLET_SIM_CORE_RAY_CONE_H

#include <random>
#include <vector>

#include <btBulletCollisionCommon.h>
#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// Yaw of horizontal ray i and pitch of vertical ray j (up positive), as Gazebo's
/// MultiRayShape spaces them: min + i * (max - min) / (samples - 1), 0 for a single one.
double coneYaw(const RayConeSpec& cone, int i);
double conePitch(const RayConeSpec& cone, int j);
/// The sensor-frame direction of a ray at yaw and pitch: (cos p cos y, cos p sin y, sin p).
Eigen::Vector3d coneDirection(double yaw_rad, double pitch_rad);

/// The range of every ray of the cone (ray j * samples + i), as Gazebo's
/// MultiRayShape::GetRange gives it: each ray is cast from range_min to range_max, and its
/// range is range_min plus the distance to its first hit, range_max when it hits nothing.
/// Walks Bullet's broadphase: one cone at a time.
std::vector<double> castRayCone(btCollisionWorld& world, const Eigen::Isometry3d& T_world_sensor,
                                const RayConeSpec& cone);

/// libgazebo_ros_range.so's reading: the smallest of `ranges`; when below range_max,
/// gaussian noise is added and the result held to range_max at most.
RangeData rangeReading(const RangeSpec& spec, const std::vector<double>& ranges,
                       std::mt19937_64* rng);

/// libgazebo_ros_block_laser.so's cloud from the cone's `ranges`: (samples * resolution) x
/// (vertical_samples * vertical_resolution) points, each range interpolated bilinearly
/// between the four rays around it, below range_min -inf and above range_max +inf (REP 117),
/// placed along the direction half way between those rays; points not at range_max get
/// gaussian noise on x, y and z, and every intensity (0: no surface here has a retro value)
/// gets it too.
BlockLaserCloudData blockLaserCloud(const BlockLaserSpec& spec, const std::vector<double>& ranges,
                               std::mt19937_64* rng);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_RAY_CONE_H
