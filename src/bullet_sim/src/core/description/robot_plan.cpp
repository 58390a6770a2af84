#include "description/robot_plan.h"

#include <algorithm>

#include <Eigen/Eigenvalues>

#include "description/description_geometry.h"

namespace bullet_sim {
namespace {

/// Smallest mass and principal inertia given to a body, so that Bullet never
/// sees a zero (static) or singular dynamic body.
constexpr double kMinMassKg = 1e-3;
constexpr double kMinInertia = 1e-7;

Eigen::Isometry3d urdfPose(const urdf::Pose& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
  T.rotate(Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z));
  return T;
}

bool isHinge(const urdf::Joint& j) {
  return j.type == urdf::Joint::REVOLUTE || j.type == urdf::Joint::CONTINUOUS;
}

class Planner {
 public:
  explicit Planner(const RobotSpec& spec) : spec_(spec) {}

  RobotPlan plan() {
    const urdf::LinkConstSharedPtr root = spec_.urdf->getRoot();
    addBody(*root, Eigen::Isometry3d::Identity());
    // A static model is one Bullet static body: mass 0, no inertia, its frame that of
    // the root link (its inertials, if any, do not matter).
    plan_.is_static = spec_.is_static;
    if (!spec_.is_static) {
      for (BodyPlan& body : plan_.bodies) finishMass(&body);
    }
    std::sort(plan_.joints.begin(), plan_.joints.end(),
              [](const JointPlan& a, const JointPlan& b) { return a.name < b.name; });
    return std::move(plan_);
  }

 private:
  /// Starts a body at `link` (at `T_model_link`) and walks its subtree.
  size_t addBody(const urdf::Link& link, const Eigen::Isometry3d& T_model_link) {
    plan_.bodies.emplace_back();
    const size_t index = plan_.bodies.size() - 1;
    plan_.bodies[index].root_link = link.name;
    addLink(index, link, Eigen::Isometry3d::Identity(), T_model_link);
    return index;
  }

  void addLink(size_t body, const urdf::Link& link, const Eigen::Isometry3d& T_root_link,
               const Eigen::Isometry3d& T_model_link) {
    plan_.bodies[body].T_root_link[link.name] = T_root_link;
    plan_.body_of_link[link.name] = body;
    plan_.T_model_link[link.name] = T_model_link;
    addMass(body, link, T_root_link);
    addCollisions(body, link, T_root_link);
    for (const urdf::LinkSharedPtr& child : link.child_links) {
      const urdf::Joint& joint = *child->parent_joint;
      const Eigen::Isometry3d T_link_child = urdfPose(joint.parent_to_joint_origin_transform);
      if (isHinge(joint) && !spec_.is_static) {
        JointPlan j;
        j.name = joint.name;
        j.parent_body = body;
        j.T_parentroot_joint = T_root_link * T_link_child;
        j.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z).normalized();
        if (joint.type == urdf::Joint::REVOLUTE && joint.limits) {
          j.limited = true;
          j.lower = joint.limits->lower;
          j.upper = joint.limits->upper;
        }
        j.child_body = addBody(*child, T_model_link * T_link_child);
        plan_.joints.push_back(j);
      } else {
        if (joint.type != urdf::Joint::FIXED && !spec_.is_static) {
          plan_.warnings.push_back("joint '" + joint.name +
                                   "': type not supported (revolute, continuous, fixed are): "
                                   "held fixed");
        }
        addLink(body, *child, T_root_link * T_link_child, T_model_link * T_link_child);
      }
    }
  }

  void addMass(size_t body, const urdf::Link& link, const Eigen::Isometry3d& T_root_link) {
    if (!link.inertial) return;
    const urdf::Inertial& in = *link.inertial;
    const Eigen::Isometry3d T_root_inertial = T_root_link * urdfPose(in.origin);
    Eigen::Matrix3d I;
    I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    masses_.push_back({body, in.mass, T_root_inertial.translation(),
                       T_root_inertial.linear() * I * T_root_inertial.linear().transpose()});
  }

  static std::string gazeboCollisionName(const BodyPlan& body, const CollisionPlan& col) {
    std::string name = (col.name.empty() ? col.link : col.name) + "_collision";
    if (!body.collisions.empty()) name += "_" + std::to_string(body.collisions.size());
    const std::string& root = body.root_link;
    if (name.compare(0, root.size(), root) == 0) return name;
    return root + "_fixed_joint_lump__" + name;
  }

  void addCollisions(size_t body, const urdf::Link& link, const Eigen::Isometry3d& T_root_link) {
    const auto surface = spec_.surfaces.find(link.name);
    const double friction =
        (surface == spec_.surfaces.end() ? SurfaceParams() : surface->second).isotropicMu();
    for (const urdf::CollisionSharedPtr& c : link.collision_array) {
      if (!c || !c->geometry) continue;
      CollisionPlan col;
      col.T_root_geom = T_root_link * urdfPose(c->origin);
      col.friction = friction;
      col.geometry() = geometryOf(*c->geometry);
      if (col.kind == Geometry::Mesh) {
        const auto mesh = spec_.collision_meshes.find(col.mesh_uri);
        if (mesh == spec_.collision_meshes.end()) {
          plan_.warnings.push_back("link '" + link.name + "': collision mesh '" + col.mesh_uri +
                                   "' was not loaded: skipped");
          continue;
        }
        col.mesh = mesh->second;
      }
      col.link = link.name;
      col.name = c->name;
      col.gazebo_name = gazeboCollisionName(plan_.bodies[body], col);
      plan_.bodies[body].collisions.push_back(col);
    }
  }

  /// Combines the masses of one body (parallel axis theorem) and finds its
  /// principal axes: Bullet wants a diagonal inertia at the centre of mass.
  void finishMass(BodyPlan* body) {
    const size_t index = static_cast<size_t>(body - plan_.bodies.data());
    double m = 0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (const PointMass& pm : masses_) {
      if (pm.body != index) continue;
      m += pm.mass;
      moment += pm.mass * pm.com;
    }
    if (m <= 0) {
      plan_.warnings.push_back("body of link '" + body->root_link +
                               "' has no mass: given " + std::to_string(kMinMassKg) + " kg");
      body->mass_kg = kMinMassKg;
      body->principal_inertia = Eigen::Vector3d::Constant(kMinInertia);
      return;
    }
    const Eigen::Vector3d com = moment / m;
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    for (const PointMass& pm : masses_) {
      if (pm.body != index) continue;
      const Eigen::Vector3d d = pm.com - com;
      I += pm.inertia + pm.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    }
    body->mass_kg = m;
    body->T_root_com = Eigen::Isometry3d::Identity();
    body->T_root_com.translate(com);
    const Eigen::Matrix3d off_diagonal = I - Eigen::Matrix3d(I.diagonal().asDiagonal());
    if (off_diagonal.cwiseAbs().maxCoeff() <= 1e-12 * I.trace()) {
      // Already principal: keeping the link's axes lets a single shape at the
      // COM be used without a compound.
      body->principal_inertia = I.diagonal().cwiseMax(kMinInertia);
      return;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
    Eigen::Matrix3d axes = eig.eigenvectors();
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
    body->T_root_com.rotate(axes);
    body->principal_inertia = eig.eigenvalues().cwiseMax(kMinInertia);
  }

  struct PointMass {
    size_t body;
    double mass;
    Eigen::Vector3d com;
    Eigen::Matrix3d inertia;  ///< about com, in the body root frame
  };
  const RobotSpec& spec_;
  RobotPlan plan_;
  std::vector<PointMass> masses_;
};

}  // namespace

RobotPlan planRobot(const RobotSpec& spec) { return Planner(spec).plan(); }

Eigen::Isometry3d toIsometry(const Pose3& pose) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(pose.position);
  T.rotate(pose.orientation.normalized());
  return T;
}

Pose3 toPose3(const Eigen::Isometry3d& T) {
  Pose3 p;
  p.position = T.translation();
  p.orientation = Eigen::Quaterniond(T.linear()).normalized();
  return p;
}

}  // namespace bullet_sim
