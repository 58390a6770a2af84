#ifndef BULLET_SIM_MODEL_PROPERTIES_H
#define BULLET_SIM_MODEL_PROPERTIES_H

#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// A link's URDF <inertial>: mass, centre of mass in the link frame, inertia about it
/// (kg m^2, in the inertial frame). All zero for a link without <inertial>.
struct LinkInertia {
  double mass_kg = 0;
  Pose3 com_in_link;
  double ixx = 0, ixy = 0, ixz = 0, iyy = 0, iyz = 0, izz = 0;
};

/// @throws std::out_of_range naming the link when the robot has none of that name.
LinkInertia linkInertia(const RobotSpec& spec, const std::string& link);

/// The names of every link's <collision> elements, link by link in name order: the
/// element's name attribute, or "<link>_collision" (then "_1", "_2", ... for further
/// unnamed ones of the same link), as Gazebo names the collisions of a URDF.
std::vector<std::string> collisionNames(const RobotSpec& spec);

/// A joint's URDF type as gazebo_msgs/GetJointProperties numbers them.
enum class JointKind { Revolute = 0, Continuous = 1, Prismatic = 2, Fixed = 3, Other = 6 };

/// @throws std::out_of_range naming the joint when the robot has none of that name.
JointKind jointKind(const RobotSpec& spec, const std::string& joint);

}  // namespace bullet_sim

#endif  // BULLET_SIM_MODEL_PROPERTIES_H
