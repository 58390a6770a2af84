#include "description/urdf/urdf_checks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <Eigen/Eigenvalues>

#include "bullet_sim/errors.h"

namespace bullet_sim {
namespace {

/// Principal moments printed from rounded tensors (4 or 5 digits) may miss the triangle
/// inequality by this much of their sum and still describe a real body (a thin disc is
/// exactly on the edge: izz = ixx + iyy).
constexpr double kTriangleTolerance = 1e-4;

}  // namespace

void checkTree(const std::vector<JointEdge>& joints, const std::string& source) {
  std::map<std::string, const JointEdge*> parent_of;  // child link -> its joint
  for (const JointEdge& joint : joints) {
    // urdfdom keys its parent table by child link: a second parent joint would silently
    // replace the first (and can hand back a cycle).
    const auto seen = parent_of.emplace(joint.child, &joint);
    if (!seen.second) {
      throw LoadError(source + ": link '" + joint.child + "' is the child of joints '" +
                      seen.first->second->name + "' and '" + joint.name +
                      "': a URDF is a tree (one parent joint per link)");
    }
  }
  // Walks up from every link; with one parent each, a walk that comes back to a link it
  // passed is a loop.
  for (const JointEdge& start_joint : joints) {
    std::vector<const JointEdge*> path;
    std::set<std::string> passed{start_joint.child};
    for (auto up = parent_of.find(start_joint.child); up != parent_of.end();
         up = parent_of.find(up->second->parent)) {
      path.push_back(up->second);
      const std::string& parent = up->second->parent;
      if (passed.insert(parent).second) continue;
      // Name the loop only, not the joints below it that the walk started from.
      const auto loop_start = std::find_if(path.begin(), path.end(), [&](const JointEdge* j) {
        return j->child == parent;
      });
      // Parent to child, from the joint written first (the edges are in document order).
      std::vector<const JointEdge*> loop(path.rbegin(), std::make_reverse_iterator(loop_start));
      std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
      std::string names;
      for (const JointEdge* j : loop) {
        names += (names.empty() ? "'" : ", '") + j->name + "' (" + j->parent + " -> " + j->child +
                 ")";
      }
      throw LoadError(source + ": joints " + names + " form a loop: a URDF is a tree");
    }
  }
}

namespace {

bool validSize(double v) { return v >= 0 && std::isfinite(v); }

/// urdfdom reads box sizes and radii as written, negative ones too.
void checkGeometry(const urdf::Geometry& g, const std::string& where) {
  std::ostringstream text;
  if (g.type == urdf::Geometry::BOX) {
    const urdf::Vector3& d = static_cast<const urdf::Box&>(g).dim;
    if (validSize(d.x) && validSize(d.y) && validSize(d.z)) return;
    text << "<box size>: '" << d.x << " " << d.y << " " << d.z << "'";
  } else if (g.type == urdf::Geometry::CYLINDER) {
    const auto& c = static_cast<const urdf::Cylinder&>(g);
    if (validSize(c.radius) && validSize(c.length)) return;
    text << "<cylinder radius length>: '" << c.radius << " " << c.length << "'";
  } else if (g.type == urdf::Geometry::SPHERE) {
    const double radius = static_cast<const urdf::Sphere&>(g).radius;
    if (validSize(radius)) return;
    text << "<sphere radius>: '" << radius << "'";
  } else {
    return;
  }
  throw LoadError(where + ": " + text.str() + " must be finite and not negative");
}

void checkGeometries(const urdf::Link& link, const std::string& source) {
  const std::string where = source + ": link '" + link.name + "'";
  for (const urdf::CollisionSharedPtr& c : link.collision_array) {
    if (c && c->geometry) checkGeometry(*c->geometry, where + " <collision>");
  }
  for (const urdf::VisualSharedPtr& v : link.visual_array) {
    if (v && v->geometry) checkGeometry(*v->geometry, where + " <visual>");
  }
}

}  // namespace

void checkInertial(const urdf::Inertial& in, const std::string& link_where) {
  const std::string where = link_where + " <inertial>";
  std::ostringstream text;
  if (!(in.mass > 0 && std::isfinite(in.mass))) {
    text << in.mass;
    throw LoadError(where + " <mass>: '" + text.str() + "' must be > 0");
  }
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  text << "ixx " << in.ixx << " ixy " << in.ixy << " ixz " << in.ixz << " iyy " << in.iyy
       << " iyz " << in.iyz << " izz " << in.izz << " has principal moments ";
  Eigen::Vector3d moments = Eigen::Vector3d::Constant(std::nan(""));
  if (I.allFinite()) moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  text << moments[0] << " " << moments[1] << " " << moments[2];
  if (!(moments.minCoeff() > 0)) {
    throw LoadError(where + " <inertia>: " + text.str() +
                    ": they must all be > 0 (the tensor must be positive definite)");
  }
  // Eigen sorts them ascending: only the largest can exceed the sum of the other two.
  if (moments[0] + moments[1] < moments[2] - kTriangleTolerance * moments.sum()) {
    throw LoadError(where + " <inertia>: " + text.str() + ": the largest exceeds the sum of " +
                    "the other two, which no rigid body allows");
  }
}

void checkUrdfModel(const urdf::ModelInterface& model, const std::string& source) {
  std::vector<JointEdge> joints;
  for (const auto& entry : model.joints_) {
    const urdf::Joint& joint = *entry.second;
    joints.push_back({joint.name, joint.parent_link_name, joint.child_link_name});
  }
  checkTree(joints, source);
  for (const auto& entry : model.links_) {
    const urdf::Link& link = *entry.second;
    if (link.inertial) checkInertial(*link.inertial, source + ": link '" + link.name + "'");
    checkGeometries(link, source);
  }
}

}  // namespace bullet_sim
