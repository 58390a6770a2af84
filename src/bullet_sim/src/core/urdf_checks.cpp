#include "urdf_checks.h"

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

/// urdfdom keys its parent table by child link, so a second parent joint silently replaces
/// the first: find it from the joints themselves.
void checkOneParentEach(const urdf::ModelInterface& model, const std::string& source) {
  std::map<std::string, std::string> parent_joint;  // child link -> joint
  for (const auto& entry : model.joints_) {
    const urdf::Joint& joint = *entry.second;
    const auto seen = parent_joint.emplace(joint.child_link_name, joint.name);
    if (!seen.second) {
      throw LoadError(source + ": link '" + joint.child_link_name + "' is the child of joints '" +
                      seen.first->second + "' and '" + joint.name +
                      "': a URDF is a tree (one parent joint per link)");
    }
  }
}

/// Walks up from every link; with one parent each, a walk that comes back to a link it
/// passed is a loop. urdfdom reports a loop only when it leaves no root link.
void checkNoLoop(const urdf::ModelInterface& model, const std::string& source) {
  std::map<std::string, const urdf::Joint*> parent_of;  // child link -> its joint
  for (const auto& entry : model.joints_) parent_of[entry.second->child_link_name] = entry.second.get();
  for (const auto& start : model.links_) {
    std::vector<const urdf::Joint*> path;
    std::set<std::string> passed{start.first};
    for (auto up = parent_of.find(start.first); up != parent_of.end();
         up = parent_of.find(up->second->parent_link_name)) {
      path.push_back(up->second);
      const std::string& parent = up->second->parent_link_name;
      if (passed.insert(parent).second) continue;
      // Name the loop only, not the joints below it that the walk started from.
      const auto loop_start = std::find_if(path.begin(), path.end(), [&](const urdf::Joint* j) {
        return j->child_link_name == parent;
      });
      std::string joints;
      for (auto j = path.rbegin(); j != std::make_reverse_iterator(loop_start); ++j) {
        joints += (joints.empty() ? "'" : ", '") + (*j)->name + "' (" + (*j)->parent_link_name +
                  " -> " + (*j)->child_link_name + ")";
      }
      throw LoadError(source + ": joints " + joints + " form a loop: a URDF is a tree");
    }
  }
}

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
  checkOneParentEach(model, source);
  checkNoLoop(model, source);
  for (const auto& entry : model.links_) {
    const urdf::Link& link = *entry.second;
    if (link.inertial) checkInertial(*link.inertial, source + ": link '" + link.name + "'");
    checkGeometries(link, source);
  }
}

}  // namespace bullet_sim
