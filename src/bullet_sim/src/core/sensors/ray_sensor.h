#ifndef BULLET_SIM_CORE_RAY_SENSOR_H
#define BULLET_SIM_CORE_RAY_SENSOR_H

#include <cstddef>
#include <random>

#include <btBulletCollisionCommon.h>
#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// Casts one planar scan as Gazebo's ray sensor does: rays lie in the sensor's
/// x-y plane, angle 0 is +x and angles grow counter-clockwise; each ray starts
/// at range_min (so the robot's own parts nearer than that are not seen);
/// nothing within range_max reads +inf; hits get gaussian noise, are rounded
/// to the range resolution and clamped to [range_min, range_max].
///
/// The shapes within range_max are listed once per scan for the rays in whose directions
/// they lie, so each ray tests only those. With more than `max_listed_parts` shapes in
/// range (compounds counted by their children), or with 0, each ray walks Bullet's
/// broadphase tree instead; both give the same ranges. Only the walk writes to the world
/// (Bullet's broadphase keeps one ray stack for every caller in a build without
/// BT_THREADSAFE): with `may_walk` false a scan that would walk is not cast, and false is
/// returned with the scan and the noise generator untouched, so that scans can be cast on
/// several threads and those that walk one at a time.
constexpr size_t kMaxListedScanParts = 512;
/// No object is ignored (every user index is -1, a robot id or above).
constexpr int kNoIgnoredIndex = -2;
bool castScan(btCollisionWorld& world, const Eigen::Isometry3d& T_world_sensor,
              const RaySpec& spec, std::mt19937_64* rng, LaserScanData* scan,
              size_t max_listed_parts = kMaxListedScanParts, bool may_walk = true);

/// Fraction of the ray from -> to at its first hit in `world`, 1 when it hits nothing (a walk
/// of Bullet's broadphase: not on several threads at once). Objects whose user index is
/// `ignored_index` (a robot's stand-ins carry its id) are passed through.
double firstHitFraction(btCollisionWorld& world, const btVector3& from, const btVector3& to,
                        int ignored_index = kNoIgnoredIndex);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_RAY_SENSOR_H
