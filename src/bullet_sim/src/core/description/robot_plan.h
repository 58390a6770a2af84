#ifndef BULLET_SIM_CORE_ROBOT_PLAN_H
#define BULLET_SIM_CORE_ROBOT_PLAN_H

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// One collision shape of a body, in the body's root-link frame (a mesh is simulated as
/// its convex hull).
struct CollisionPlan : Geometry {
  std::shared_ptr<const TriangleMesh> mesh;  ///< Mesh only
  Eigen::Isometry3d T_root_geom = Eigen::Isometry3d::Identity();
  double friction = 1.0;          ///< from the link's mu1/mu2
};

/// A rigid body: links joined by fixed joints, merged. Frames are given in the
/// frame of the body's root link (the one nearest the robot's root).
struct BodyPlan {
  std::string root_link;
  std::map<std::string, Eigen::Isometry3d> T_root_link;  ///< every merged link
  double mass_kg = 0;
  Eigen::Isometry3d T_root_com = Eigen::Isometry3d::Identity();  ///< principal axes at the COM
  Eigen::Vector3d principal_inertia{0, 0, 0};
  std::vector<CollisionPlan> collisions;
};

/// A movable joint between two bodies (revolute or continuous: a hinge).
struct JointPlan {
  std::string name;
  bool limited = false;
  double lower = 0, upper = 0;
  size_t parent_body = 0, child_body = 0;
  Eigen::Isometry3d T_parentroot_joint = Eigen::Isometry3d::Identity();  ///< joint frame at 0
  Eigen::Vector3d axis{0, 0, 1};  ///< in the joint frame (= child root-link frame)
};

/// The bodies and hinges a robot is built from. Body 0 holds the URDF root link.
struct RobotPlan {
  std::vector<BodyPlan> bodies;
  std::vector<JointPlan> joints;  ///< every hinge, sorted by name
  std::map<std::string, size_t> body_of_link;
  std::map<std::string, Eigen::Isometry3d> T_model_link;  ///< link poses at zero joint angles
  std::vector<std::string> warnings;
  bool is_static = false;  ///< one body of mass 0 (RobotSpec::is_static)
};

/// Groups a URDF's links into bodies, combines their mass and inertia, and
/// lists the hinges. Unsupported joint types (prismatic, planar, floating)
/// are held fixed with a warning. A mesh collision takes its mesh from
/// spec.collision_meshes (one that is not there is skipped with a warning).
RobotPlan planRobot(const RobotSpec& spec);

Eigen::Isometry3d toIsometry(const Pose3& pose);
Pose3 toPose3(const Eigen::Isometry3d& T);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_ROBOT_PLAN_H
