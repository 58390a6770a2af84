#include "sensors/ground_truth.h"

namespace bullet_sim {

OdometryData readGroundTruth(const P3dSpec& spec, const LinkMotion& body,
                             const LinkMotion* frame, double time_s, std::mt19937_64* rng) {
  Eigen::Vector3d position = body.T_world_link.translation();
  Eigen::Quaterniond orientation(body.T_world_link.linear());
  Twist3 v = body.velocity;
  if (frame) {
    const Eigen::Matrix3d R_frame = frame->T_world_link.linear();
    position = R_frame.transpose() * (position - frame->T_world_link.translation());
    orientation = orientation * Eigen::Quaterniond(R_frame).inverse();
    v.linear = R_frame * (v.linear - frame->velocity.linear);
    v.angular = R_frame * (v.angular - frame->velocity.angular);
  }
  OdometryData odom;
  odom.time_s = time_s;
  odom.frame_id = spec.frame;
  odom.child_frame_id = spec.body;
  odom.pose.position = position + spec.offset.position;
  odom.pose.orientation = (spec.offset.orientation * orientation).normalized();
  std::normal_distribution<double> noise(0.0, spec.gaussian_noise);
  const bool noisy = spec.gaussian_noise > 0;
  for (int i = 0; i < 3; ++i) odom.twist_in_child.linear[i] = v.linear[i] + (noisy ? noise(*rng) : 0);
  for (int i = 0; i < 3; ++i) odom.twist_in_child.angular[i] = v.angular[i] + (noisy ? noise(*rng) : 0);
  const double variance = spec.gaussian_noise * spec.gaussian_noise;
  for (int i = 0; i < 6; ++i) odom.pose_covariance[i * 7] = odom.twist_covariance[i * 7] = variance;
  return odom;
}

}  // namespace bullet_sim
