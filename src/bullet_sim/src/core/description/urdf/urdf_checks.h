#ifndef BULLET_SIM_CORE_URDF_CHECKS_H
#define BULLET_SIM_CORE_URDF_CHECKS_H

#include <string>
#include <vector>

#include <urdf_model/model.h>

namespace bullet_sim {

/// What urdfdom accepts but no simulator can build: a link that is the child of two joints,
/// joints that close a loop (urdfdom keeps one parent per link and may leave a loop out of
/// the tree, or hand back a cycle), an <inertial> with a mass that is not positive, or an
/// inertia tensor that is not positive definite or breaks the triangle inequality of its
/// principal moments (no rigid body has those), a negative or non-finite box size, cylinder
/// radius or length, or sphere radius.
/// @throws LoadError naming `source`, the link or joints and the values.
void checkUrdfModel(const urdf::ModelInterface& model, const std::string& source);

/// A joint as the tree sees it: its name, parent link and child link.
struct JointEdge {
  std::string name, parent, child;
};

/// That the joints make a tree: no link is the child of two joints, and no joints close a
/// loop (urdfdom reports a loop only when it leaves no root link).
/// @throws LoadError naming `source`, the link's two joints, or the loop's joints in order,
/// parent -> child.
void checkTree(const std::vector<JointEdge>& joints, const std::string& source);

/// The mass and inertia check of checkUrdfModel for one link (SDF models converted to URDF
/// links use it too). `link_where` starts the message ("file: link 'base'").
/// @throws LoadError naming the link and the values.
void checkInertial(const urdf::Inertial& inertial, const std::string& link_where);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_URDF_CHECKS_H
