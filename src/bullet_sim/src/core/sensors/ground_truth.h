#ifndef BULLET_SIM_CORE_GROUND_TRUTH_H
#define BULLET_SIM_CORE_GROUND_TRUTH_H

#include <random>

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/sensors/sensor_data.h"

namespace bullet_sim {

/// The state of a link in the world: its pose and the velocity of its origin.
struct LinkMotion {
  Eigen::Isometry3d T_world_link = Eigen::Isometry3d::Identity();
  Twist3 velocity;  ///< world axes
};

/// libgazebo_ros_p3d.so's reading of `body` (Noetic's formulas): the pose in the world, or
/// relative to `frame` (a link of the same model) when one is given: position
/// R_frame^T (p - p_frame), orientation q q_frame^-1; then the offsets: position + xyzOffset,
/// orientation rpyOffset * q. The twist is the body's world velocity, or relative to the
/// frame R_frame (v - v_frame) (Gazebo turns the difference by the frame's rotation, not
/// its inverse), each of its six fields plus Gaussian noise of sd gaussianNoise; both
/// covariances hold gaussianNoise^2 on the diagonal. Frame ids: `frame_id` the plugin's
/// frameName, child the body's name.
OdometryData readGroundTruth(const P3dSpec& spec, const LinkMotion& body,
                             const LinkMotion* frame, double time_s, std::mt19937_64* rng);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_GROUND_TRUTH_H
