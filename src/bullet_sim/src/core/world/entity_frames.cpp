#include "bullet_sim/world/entity_frames.h"

namespace bullet_sim {

bool isWorldFrameName(const std::string& name) { return name.empty() || name == "world"; }

EntityState expressIn(const EntityState& entity, const EntityState& frame) {
  const Eigen::Quaterniond q_frame = frame.pose.orientation.normalized();
  const Eigen::Matrix3d R_world_frame = q_frame.toRotationMatrix();
  EntityState relative;
  relative.pose.position = R_world_frame.transpose() * (entity.pose.position - frame.pose.position);
  relative.pose.orientation = (q_frame.conjugate() * entity.pose.orientation).normalized();
  relative.twist.linear = R_world_frame.transpose() * (entity.twist.linear - frame.twist.linear);
  relative.twist.angular = R_world_frame.transpose() * (entity.twist.angular - frame.twist.angular);
  return relative;
}

EntityState stateInWorld(const EntityState& relative, const Pose3& frame) {
  const Eigen::Quaterniond q_frame = frame.orientation.normalized();
  EntityState world;
  world.pose.position = frame.position + q_frame * relative.pose.position;
  world.pose.orientation = (q_frame * relative.pose.orientation.normalized()).normalized();
  world.twist.linear = q_frame * relative.twist.linear;
  world.twist.angular = q_frame * relative.twist.angular;
  return world;
}

Wrench wrenchInWorld(const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
                     const Eigen::Vector3d& reference_point,
                     const Eigen::Quaterniond& frame_orientation) {
  const Eigen::Quaterniond q = frame_orientation.normalized();
  Wrench w;
  w.force_n = q * force;
  w.torque_nm = q * (torque + reference_point.cross(force));
  return w;
}

bool isUsablePose(const Pose3& pose) {
  return pose.position.allFinite() && pose.orientation.coeffs().allFinite();
}

bool isFiniteTwist(const Twist3& twist) {
  return twist.linear.allFinite() && twist.angular.allFinite();
}

}  // namespace bullet_sim
