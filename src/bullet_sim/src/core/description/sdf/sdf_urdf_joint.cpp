#include "description/sdf/sdf_urdf_joint.h"

#include <memory>

#include "description/sdf/sdf_urdf_convert.h"

namespace bullet_sim {
namespace {

using Eigen::Isometry3d;

/// SDF writes an unlimited revolute joint as limits beyond +-1e16.
constexpr double kUnlimited = 1e15;

urdf::JointLimitsSharedPtr limitsOf(const SdfJointAxis& axis) {
  auto l = std::make_shared<urdf::JointLimits>();
  l->lower = axis.lower;
  l->upper = axis.upper;
  l->effort = axis.effort;
  l->velocity = axis.velocity;
  return l;
}

/// The URDF type and limits of `j`; an unsupported type is held fixed, with a warning.
void setType(const JointEntry& j, const std::string& where, urdf::Joint* joint,
             std::vector<std::string>* warnings) {
  const std::optional<SdfJointAxis>& axis = j.joint->axis;
  const std::string& type = j.joint->type;
  if (type == "fixed") {
    joint->type = urdf::Joint::FIXED;
  } else if (type == "continuous") {
    joint->type = urdf::Joint::CONTINUOUS;
  } else if (type == "revolute") {
    joint->type = axis && (axis->lower > -kUnlimited || axis->upper < kUnlimited)
                      ? urdf::Joint::REVOLUTE
                      : urdf::Joint::CONTINUOUS;
    if (joint->type == urdf::Joint::REVOLUTE) joint->limits = limitsOf(*axis);
  } else if (type == "prismatic") {
    joint->type = urdf::Joint::PRISMATIC;
    if (axis) joint->limits = limitsOf(*axis);
  } else {
    warnings->push_back(where + ": joint '" + j.name + "': type not supported " +
                        "(revolute, continuous, prismatic, fixed are): held fixed");
    joint->type = urdf::Joint::FIXED;
  }
}

urdf::JointSharedPtr makeJoint(const JointEntry& j, const std::string& where,
                               std::vector<std::string>* warnings) {
  auto joint = std::make_shared<urdf::Joint>();
  joint->name = j.name;
  setType(j, where, joint.get(), warnings);
  const std::optional<SdfJointAxis>& axis = j.joint->axis;
  if (axis && joint->type != urdf::Joint::FIXED) {
    joint->dynamics = std::make_shared<urdf::JointDynamics>();
    joint->dynamics->damping = axis->damping;
    joint->dynamics->friction = axis->friction;
  }
  return joint;
}

/// The massless link `j.name`_frame at the joint, and its fixed joint to `child`.
void addJointFrame(const JointEntry& j, const LinkEntry& child,
                   const Isometry3d& T_joint_child, urdf::ModelInterface* urdf) {
  const std::string frame = j.name + "_frame";
  auto frame_link = std::make_shared<urdf::Link>();
  frame_link->name = frame;
  urdf->links_[frame] = frame_link;
  auto fixed = std::make_shared<urdf::Joint>();
  fixed->name = j.name + "_frame_to_child";
  fixed->type = urdf::Joint::FIXED;
  fixed->parent_link_name = frame;
  fixed->child_link_name = child.name;
  fixed->parent_to_joint_origin_transform = toUrdfPose(T_joint_child);
  urdf->joints_[fixed->name] = fixed;
}

}  // namespace

void addUrdfJoint(const JointEntry& j, const LinkEntry& parent, const LinkEntry& child,
                  const std::string& where, urdf::ModelInterface* urdf,
                  std::vector<std::string>* warnings) {
  const Isometry3d T_joint_child = j.T_model_joint.inverse() * child.T_model_link;
  auto joint = makeJoint(j, where, warnings);
  joint->parent_link_name = parent.name;
  joint->parent_to_joint_origin_transform =
      toUrdfPose(parent.T_model_link.inverse() * j.T_model_joint);
  const Eigen::Vector3d axis = j.T_model_joint.linear().transpose() * j.axis_in_model;
  joint->axis = urdf::Vector3(axis.x(), axis.y(), axis.z());
  if (T_joint_child.isApprox(Isometry3d::Identity(), 1e-9)) {
    joint->child_link_name = child.name;
  } else {
    joint->child_link_name = j.name + "_frame";
    addJointFrame(j, child, T_joint_child, urdf);
  }
  urdf->joints_[joint->name] = joint;
}

}  // namespace bullet_sim
