// PhysicsRobot: the loads put on its bodies and joints, and what they read back.
#include "physics/bullet_convert.h"
#include "physics/physics_robot.h"

namespace bullet_sim {

void PhysicsRobot::applyLinkWrench(const std::string& link, const Wrench& wrench) {
  const size_t body = plan_.body_of_link.at(link);
  btRigidBody& rb = *bodies_[body].rigid;
  rb.activate(true);
  rb.applyCentralForce(toBt(wrench.force_n));
  rb.applyTorque(toBt(wrench.torque_nm));
  body_loads_pending_[body].force_n += wrench.force_n;
  body_loads_pending_[body].torque_nm += wrench.torque_nm;
}

void PhysicsRobot::applyJointEffort(size_t joint, double effort_nm) {
  btHingeConstraint& h = *hinges_[joint];
  const btVector3 torque = jointAxisInWorld(joint) * effort_nm;
  h.getRigidBodyA().activate(true);
  h.getRigidBodyB().activate(true);
  h.getRigidBodyB().applyTorque(torque);
  h.getRigidBodyA().applyTorque(-torque);
  const JointPlan& j = plan_.joints[joint];
  body_loads_pending_[j.child_body].torque_nm += toEigen(torque);
  body_loads_pending_[j.parent_body].torque_nm -= toEigen(torque);
  effort_pending_nm_[joint] += effort_nm;
}

void PhysicsRobot::latchAppliedLoads() {
  body_loads_last_.swap(body_loads_pending_);
  body_loads_pending_.assign(bodies_.size(), Wrench());
  effort_last_nm_.swap(effort_pending_nm_);
  effort_pending_nm_.assign(hinges_.size(), 0.0);
}

Wrench PhysicsRobot::appliedWrench(size_t body) const { return body_loads_last_.at(body); }

Wrench PhysicsRobot::jointWrenchOnChild(size_t joint) const {
  const btJointFeedback& fb = feedback_.at(joint);
  Wrench w;
  w.force_n = toEigen(fb.m_appliedForceBodyB);
  w.torque_nm = toEigen(fb.m_appliedTorqueBodyB) +
                toEigen(jointAxisInWorld(joint)) * effort_last_nm_[joint];
  return w;
}

Eigen::Vector3d PhysicsRobot::bodyCentreOfMass(size_t body) const {
  return T_world_body(body).translation();
}

}  // namespace bullet_sim
