// Simulation: what set_link_properties, set_joint_properties, the solver settings and the
// light services change.
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "bullet_sim/description/model_properties.h"
#include "description/robot_plan.h"
#include "simulation_impl.h"

namespace bullet_sim {
namespace {

std::string number(double v) {
  std::ostringstream text;
  text << v;
  return text.str();
}

void requireFinite(double v, const std::string& field) {
  if (!std::isfinite(v)) throw std::invalid_argument(field + " " + number(v) + " is not finite");
}

/// The inertia tensor of `p` in its inertial axes.
Eigen::Matrix3d tensorOf(const LinkProperties& p) {
  Eigen::Matrix3d I;
  I << p.ixx, p.ixy, p.ixz, p.ixy, p.iyy, p.iyz, p.ixz, p.iyz, p.izz;
  return I;
}

/// The other links merged with `link` into its body, as a list for a message.
std::string mergedWith(const BodyPlan& body, const std::string& link) {
  std::string names;
  for (const auto& entry : body.T_root_link) {
    if (entry.first == link) continue;
    names += (names.empty() ? "'" : ", '") + entry.first + "'";
  }
  return names;
}

/// The principal moments of `p`'s inertia in the principal axes of `body` (the link being
/// the body's only link); throws when the tensor is not diagonal in those axes.
Eigen::Vector3d principalMoments(const LinkProperties& p, const LinkProperties& current,
                                 const BodyPlan& body) {
  // Inertial axes in the link frame are those of the link's current inertial (Gazebo's
  // set_link_properties does not turn them either); the body's principal axes are
  // T_root_com's, the link being the body's root.
  const Eigen::Matrix3d R_link_inertial = current.com_in_link.orientation.toRotationMatrix();
  const Eigen::Matrix3d R_link_principal = body.T_root_com.linear();
  const Eigen::Matrix3d R = R_link_inertial.transpose() * R_link_principal;
  const Eigen::Matrix3d I = R.transpose() * tensorOf(p) * R;
  const double scale = std::max(I.diagonal().cwiseAbs().sum(), 1e-12);
  const double off = std::abs(I(0, 1)) + std::abs(I(0, 2)) + std::abs(I(1, 2));
  if (off > 1e-6 * scale) {
    throw std::invalid_argument(
        "inertia (ixx " + number(p.ixx) + " ixy " + number(p.ixy) + " ixz " + number(p.ixz) +
        " iyy " + number(p.iyy) + " iyz " + number(p.iyz) + " izz " + number(p.izz) +
        ") is not diagonal in the link's principal axes: Bullet keeps a body's principal "
        "axes, give a tensor with the same axes as the link's inertia");
  }
  const Eigen::Vector3d d = I.diagonal();
  if (!(d.minCoeff() > 0)) {
    throw std::invalid_argument("inertia: principal moments " + number(d.x()) + " " +
                                number(d.y()) + " " + number(d.z()) + " must all be > 0");
  }
  return d;
}

void applyJointDynamics(PhysicsRobot& physics, size_t joint, const JointDynamics& d) {
  if (d.damping_nms_per_rad) physics.setJointDamping(joint, *d.damping_nms_per_rad);
  if (d.lower_rad && d.upper_rad) physics.setJointLimits(joint, *d.lower_rad, *d.upper_rad);
  if (d.erp) physics.setJointParam(joint, BT_CONSTRAINT_ERP, *d.erp);
  if (d.cfm) physics.setJointParam(joint, BT_CONSTRAINT_CFM, *d.cfm);
  if (d.stop_erp) physics.setJointParam(joint, BT_CONSTRAINT_STOP_ERP, *d.stop_erp);
  if (d.stop_cfm) physics.setJointParam(joint, BT_CONSTRAINT_STOP_CFM, *d.stop_cfm);
  if (d.motor_velocity_radps && d.motor_max_torque_nm) {
    physics.setJointMotor(joint, *d.motor_velocity_radps, *d.motor_max_torque_nm);
  }
}

}  // namespace

void Simulation::Impl::applyPropertyChanges(Robot& r) const {
  PhysicsRobot& physics = *r.physics;
  for (const auto& entry : r.link_changes) {
    const size_t body = physics.bodyOfLink(entry.first);
    const LinkProperties& p = entry.second;
    if (physics.plan().bodies[body].T_root_link.size() == 1) {
      const Eigen::Matrix3d R = physics.plan().bodies[body].T_root_com.linear();
      const Eigen::Matrix3d R_inertial = p.com_in_link.orientation.toRotationMatrix();
      const Eigen::Matrix3d I =
          (R_inertial.transpose() * R).transpose() * tensorOf(p) * (R_inertial.transpose() * R);
      physics.setBodyMass(body, p.mass_kg, I.diagonal());
    }
    physics.setBodyGravity(body, p.gravity);
  }
  for (const auto& entry : r.joint_changes) {
    applyJointDynamics(physics, static_cast<size_t>(physics.jointIndex(entry.first)),
                       entry.second);
  }
}

SolverSettings Simulation::solverSettings() const { return impl_->solver; }

void Simulation::setSolverSettings(const SolverSettings& s) {
  if (s.iterations < 1) {
    throw std::invalid_argument("solver iterations " + std::to_string(s.iterations) +
                                " must be >= 1");
  }
  if (!(std::isfinite(s.sor) && s.sor > 0)) {
    throw std::invalid_argument("solver SOR " + number(s.sor) + " must be > 0");
  }
  if (!(s.erp >= 0 && s.erp <= 1)) {
    throw std::invalid_argument("solver ERP " + number(s.erp) + " must be in [0, 1]");
  }
  if (!(std::isfinite(s.cfm) && s.cfm >= 0)) {
    throw std::invalid_argument("solver CFM " + number(s.cfm) + " must be >= 0");
  }
  impl_->solver = s;
  impl_->physics->setSolver(s);
}

bool Simulation::setLight(const LightSpec& light) {
  std::vector<LightSpec>& lights = impl_->world.lights;
  for (LightSpec& l : lights) {
    if (l.name != light.name) continue;
    l = light;
    return true;
  }
  return false;
}

bool Simulation::deleteLight(const std::string& name) {
  std::vector<LightSpec>& lights = impl_->world.lights;
  for (auto it = lights.begin(); it != lights.end(); ++it) {
    if (it->name != name) continue;
    lights.erase(it);
    return true;
  }
  return false;
}

LinkProperties Simulation::linkProperties(const std::string& robot,
                                          const std::string& link) const {
  const Impl::Robot& r = impl_->robot(robot);
  if (!r.physics->hasLink(link)) {
    throw std::out_of_range("model '" + robot + "' has no link '" + link + "'");
  }
  const auto changed = r.link_changes.find(link);
  if (changed != r.link_changes.end()) return changed->second;
  const LinkInertia in = linkInertia(r.spec, link);
  LinkProperties p;
  p.mass_kg = in.mass_kg;
  p.com_in_link = in.com_in_link;
  p.ixx = in.ixx;
  p.ixy = in.ixy;
  p.ixz = in.ixz;
  p.iyy = in.iyy;
  p.iyz = in.iyz;
  p.izz = in.izz;
  return p;
}

void Simulation::setLinkProperties(const std::string& robot, const std::string& link,
                                   const LinkProperties& requested) {
  const LinkProperties current = linkProperties(robot, link);
  Impl::Robot& r = impl_->robot(robot);
  requireFinite(requested.mass_kg, "mass");
  const Eigen::Vector3d& c = requested.com_in_link.position;
  requireFinite(c.x(), "com.position.x");
  requireFinite(c.y(), "com.position.y");
  requireFinite(c.z(), "com.position.z");
  for (double v : {requested.ixx, requested.ixy, requested.ixz, requested.iyy, requested.iyz,
                   requested.izz}) {
    requireFinite(v, "inertia");
  }
  const size_t body = r.physics->bodyOfLink(link);
  const BodyPlan& plan = r.physics->plan().bodies[body];
  const bool alone = plan.T_root_link.size() == 1;
  const std::string where = "link '" + link + "' is joined by fixed joints with " +
                            mergedWith(plan, link) + " into one rigid body: ";
  const bool mass_changed = requested.mass_kg != current.mass_kg ||
                            tensorOf(requested) != tensorOf(current) ||
                            (c - current.com_in_link.position).norm() > 1e-9;
  LinkProperties stored = requested;
  stored.com_in_link = current.com_in_link;
  Eigen::Vector3d moments = plan.principal_inertia;
  if (mass_changed) {
    if (!alone) throw std::invalid_argument(where + "its mass and inertia cannot be set alone");
    if (!(requested.mass_kg > 0)) {
      throw std::invalid_argument("mass " + number(requested.mass_kg) + " must be > 0 kg");
    }
    if ((c - current.com_in_link.position).norm() > 1e-9) {
      const Eigen::Vector3d& o = current.com_in_link.position;
      throw std::invalid_argument("com.position (" + number(c.x()) + ", " + number(c.y()) +
                                  ", " + number(c.z()) + ") differs from the link's centre "
                                  "of mass (" + number(o.x()) + ", " + number(o.y()) + ", " +
                                  number(o.z()) + "): it cannot be moved");
    }
    moments = principalMoments(requested, current, plan);
  }
  if (requested.gravity != current.gravity && !alone) {
    throw std::invalid_argument(where + "gravity_mode is set per body, not for one link");
  }
  if (mass_changed) r.physics->setBodyMass(body, requested.mass_kg, moments);
  r.physics->setBodyGravity(body, requested.gravity);
  r.link_changes[link] = stored;
}

JointDynamics Simulation::jointDynamics(const std::string& robot, const std::string& joint) const {
  const Impl::Robot& r = impl_->robot(robot);
  const int index = r.physics->jointIndex(joint);
  if (index < 0) {
    throw std::out_of_range("model '" + robot + "' has no movable joint '" + joint + "'");
  }
  JointDynamics d;
  const auto changed = r.joint_changes.find(joint);
  if (changed != r.joint_changes.end()) d = changed->second;
  const JointPlan& plan = r.physics->plan().joints[static_cast<size_t>(index)];
  if (plan.limited) {
    d.lower_rad = plan.lower;
    d.upper_rad = plan.upper;
  }
  if (!d.damping_nms_per_rad) d.damping_nms_per_rad = 0.0;
  return d;
}

void Simulation::setJointDynamics(const std::string& robot, const std::string& joint,
                                  const JointDynamics& requested) {
  JointDynamics merged = jointDynamics(robot, joint);
  Impl::Robot& r = impl_->robot(robot);
  const auto check = [](const std::optional<double>& v, const std::string& field, double lo,
                        double hi) {
    if (!v) return;
    if (!(*v >= lo && *v <= hi)) {
      throw std::invalid_argument(field + " " + number(*v) + " must be in [" + number(lo) +
                                  ", " + number(hi) + "]");
    }
  };
  const double inf = std::numeric_limits<double>::infinity();
  check(requested.damping_nms_per_rad, "damping", 0, std::numeric_limits<double>::max());
  check(requested.lower_rad, "loStop", -inf, inf);
  check(requested.upper_rad, "hiStop", -inf, inf);
  check(requested.erp, "erp", 0, 1);
  check(requested.stop_erp, "stop_erp", 0, 1);
  check(requested.cfm, "cfm", 0, std::numeric_limits<double>::max());
  check(requested.stop_cfm, "stop_cfm", 0, std::numeric_limits<double>::max());
  check(requested.motor_velocity_radps, "vel", -std::numeric_limits<double>::max(),
        std::numeric_limits<double>::max());
  check(requested.motor_max_torque_nm, "fmax", 0, std::numeric_limits<double>::max());
  if (requested.motor_velocity_radps.has_value() != requested.motor_max_torque_nm.has_value()) {
    throw std::invalid_argument("vel and fmax drive the joint's motor together: give both");
  }
  const bool one_limit = requested.lower_rad.has_value() != requested.upper_rad.has_value();
  if (one_limit && !(merged.lower_rad && merged.upper_rad)) {
    throw std::invalid_argument(std::string(requested.lower_rad ? "loStop" : "hiStop") +
                                " given alone for a joint without limits: give both");
  }
  for (std::optional<double> JointDynamics::*field :
       {&JointDynamics::damping_nms_per_rad, &JointDynamics::lower_rad, &JointDynamics::upper_rad,
        &JointDynamics::erp, &JointDynamics::cfm, &JointDynamics::stop_erp,
        &JointDynamics::stop_cfm, &JointDynamics::motor_velocity_radps,
        &JointDynamics::motor_max_torque_nm}) {
    if (requested.*field) merged.*field = requested.*field;
  }
  r.joint_changes[joint] = merged;
  applyJointDynamics(*r.physics, static_cast<size_t>(r.physics->jointIndex(joint)), merged);
}

}  // namespace bullet_sim
