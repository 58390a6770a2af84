#include "physics/physics_robot.h"

#include <algorithm>
#include <cmath>

#include "physics/bullet_convert.h"
#include "physics/collision_shapes.h"

namespace bullet_sim {
namespace {

/// Below these speeds for a while a robot's bodies go to sleep (m/s, rad/s).
constexpr double kSleepLinearMps = 0.002;
constexpr double kSleepAngularRadps = 0.01;
/// How fast a motor pulls its joint back onto the reference angle (1/s).
constexpr double kMotorStiffnessPerS = 20.0;
/// Largest reference lag a motor keeps (rad).
constexpr double kMaxMotorLagRad = 0.05;

/// With the reference frame on the parent, Bullet's hinge angle and motor
/// velocity are the child's rotation about the axis, as URDF defines them.
constexpr bool kAngleOfChildInParent = true;

double wrapToPi(double a) {
  // remainder() gives `a` itself within +-pi (a tie at pi keeps the even quotient 0); a
  // hinge's angle changes far less than that in a step, and remainder() costs ~60
  // instructions.
  if (std::fabs(a) <= M_PI) return a;
  return std::remainder(a, 2.0 * M_PI);
}

}  // namespace

PhysicsRobot::PhysicsRobot(btDiscreteDynamicsWorld* world, int robot_id, RobotPlan plan,
                           const Eigen::Isometry3d& T_world_model)
    : world_(world), plan_(std::move(plan)) {
  bodies_.reserve(plan_.bodies.size());
  for (const BodyPlan& b : plan_.bodies) buildBody(b, robot_id);
  placeBodies(T_world_model);
  feedback_.resize(plan_.joints.size());
  for (const JointPlan& j : plan_.joints) {
    const Eigen::Quaterniond align =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), j.axis);
    const Eigen::Isometry3d frame_in_parent =
        bodies_[j.parent_body].T_com_root * j.T_parentroot_joint * Eigen::Isometry3d(align);
    const Eigen::Isometry3d frame_in_child = bodies_[j.child_body].T_com_root * Eigen::Isometry3d(align);
    auto hinge = std::make_unique<btHingeConstraint>(
        *bodies_[j.parent_body].rigid, *bodies_[j.child_body].rigid, toBt(frame_in_parent),
        toBt(frame_in_child), kAngleOfChildInParent);
    if (j.limited) hinge->setLimit(j.lower, j.upper);
    hinge->enableFeedback(true);
    hinge->setJointFeedback(&feedback_[hinges_.size()]);
    world_->addConstraint(hinge.get(), true);
    hinges_.push_back(std::move(hinge));
  }
  joint_angles_.assign(hinges_.size(), 0.0);
  motors_.assign(hinges_.size(), Motor());
  damping_.assign(hinges_.size(), 0.0);
  body_loads_pending_.assign(bodies_.size(), Wrench());
  body_loads_last_.assign(bodies_.size(), Wrench());
  effort_pending_nm_.assign(hinges_.size(), 0.0);
  effort_last_nm_.assign(hinges_.size(), 0.0);
  last_raw_angles_.assign(hinges_.size(), 0.0);
}

PhysicsRobot::~PhysicsRobot() {
  for (auto& h : hinges_) world_->removeConstraint(h.get());
  for (auto& b : bodies_) world_->removeRigidBody(b.rigid.get());
}

void PhysicsRobot::buildBody(const BodyPlan& plan, int robot_id) {
  Body body;
  body.T_com_root = plan.T_root_com.inverse();
  body.material.robot_id = robot_id;
  // A static robot's bodies have no mass: Bullet never moves them (a mesh keeps its
  // triangles, as the world's static shapes do).
  const Motion motion = plan_.is_static ? Motion::Static : Motion::Moving;
  const double mass_kg = plan_.is_static ? 0.0 : plan.mass_kg;
  const Eigen::Vector3d inertia =
      plan_.is_static ? Eigen::Vector3d::Zero() : Eigen::Vector3d(plan.principal_inertia);
  const bool single_at_com =
      plan.collisions.size() == 1 &&
      (body.T_com_root * plan.collisions[0].T_root_geom).isApprox(Eigen::Isometry3d::Identity(), 1e-12);
  if (plan.collisions.empty()) {
    body.shape = std::make_unique<btEmptyShape>();
  } else if (single_at_com) {
    // Saves the compound's per-step overhead (the Burger's wheels). Its friction is the
    // body's own (set below).
    body.shape = makeCollisionShape(plan.collisions[0], plan.collisions[0].mesh.get(), motion);
  } else {
    // A robot body has a handful of parts: a linear scan beats a child AABB tree.
    auto compound =
        std::make_unique<btCompoundShape>(false, static_cast<int>(plan.collisions.size()));
    for (const CollisionPlan& c : plan.collisions) {
      body.children.push_back(makeCollisionShape(c, c.mesh.get(), motion));
      compound->addChildShape(toBt(body.T_com_root * c.T_root_geom), body.children.back().get());
      body.material.child_friction.push_back(c.friction);
    }
    body.shape = std::move(compound);
  }
  // No motion state: poses are read from the bodies, so Bullet need not copy
  // them out after every step.
  btRigidBody::btRigidBodyConstructionInfo info(mass_kg, nullptr, body.shape.get(),
                                                toBt(inertia));
  body.rigid = std::make_unique<btRigidBody>(info);
  if (single_at_com) body.rigid->setFriction(plan.collisions[0].friction);
  // A robot that has come to rest sleeps, as resting bodies do in Bullet: its
  // contacts then cannot creep. Commands, teleports and contacts wake it
  // (Bullet lets a body sleep after 2 s below these speeds).
  body.rigid->setSleepingThresholds(kSleepLinearMps, kSleepAngularRadps);
  // ODE (Gazebo) integrates no gyroscopic term either; it costs a third of a step.
  body.rigid->setFlags(body.rigid->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
  body.rigid->setUserIndex(robot_id);
  bodies_.push_back(std::move(body));
  Body& stored = bodies_.back();
  stored.rigid->setUserPointer(&stored.material);
  if (!plan.collisions.empty()) {
    stored.rigid->setCollisionFlags(stored.rigid->getCollisionFlags() |
                                    btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
  }
  addBody(stored.rigid.get(), !plan.collisions.empty());
}

void PhysicsRobot::addBody(btRigidBody* body, bool collides) {
  // A link without collision (the flag) is never touched and never seen by rays.
  if (collides) {
    world_->addRigidBody(body);
  } else {
    world_->addRigidBody(body, 0, 0);
  }
}

void PhysicsRobot::moveToWorld(btDiscreteDynamicsWorld* world) {
  if (world == world_) return;
  for (auto& h : hinges_) world_->removeConstraint(h.get());
  for (auto& b : bodies_) world_->removeRigidBody(b.rigid.get());
  world_ = world;
  for (size_t i = 0; i < bodies_.size(); ++i) {
    addBody(bodies_[i].rigid.get(), !plan_.bodies[i].collisions.empty());
  }
  for (auto& h : hinges_) world_->addConstraint(h.get(), true);
}

std::vector<const btRigidBody*> PhysicsRobot::collidingBodies() const {
  std::vector<const btRigidBody*> colliding;
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (!plan_.bodies[i].collisions.empty()) colliding.push_back(bodies_[i].rigid.get());
  }
  return colliding;
}

bool PhysicsRobot::bounds(btVector3* aabb_min, btVector3* aabb_max, double* speed_mps) const {
  bool any = false;
  *speed_mps = 0;
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (plan_.bodies[i].collisions.empty()) continue;
    const btRigidBody* body = bodies_[i].rigid.get();
    btVector3 lo, hi;
    body->getCollisionShape()->getAabb(body->getWorldTransform(), lo, hi);
    if (!any) {
      *aabb_min = lo;
      *aabb_max = hi;
    } else {
      aabb_min->setMin(lo);
      aabb_max->setMax(hi);
    }
    any = true;
    // A point of the body is at most the box's diagonal from its centre of mass.
    const double speed = body->getLinearVelocity().length() +
                         body->getAngularVelocity().length() * (hi - lo).length();
    *speed_mps = std::max(*speed_mps, speed);
  }
  return any;
}

void PhysicsRobot::placeBodies(const Eigen::Isometry3d& T_world_model) {
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const Eigen::Isometry3d T_model_root = plan_.T_model_link.at(plan_.bodies[i].root_link);
    const Eigen::Isometry3d T_world_com = T_world_model * T_model_root * plan_.bodies[i].T_root_com;
    btRigidBody& rb = *bodies_[i].rigid;
    rb.setWorldTransform(toBt(T_world_com));
    rb.setInterpolationWorldTransform(rb.getWorldTransform());
  }
}

void PhysicsRobot::moveRoot(const Eigen::Isometry3d& T_world_root, const Twist3& twist) {
  const Eigen::Isometry3d T_new_old = T_world_root * linkPose(plan_.bodies[0].root_link).inverse();
  const Eigen::Vector3d origin = T_world_root.translation();
  for (Body& b : bodies_) {
    btRigidBody& rb = *b.rigid;
    const Eigen::Isometry3d T = T_new_old * toEigen(rb.getWorldTransform());
    rb.setWorldTransform(toBt(T));
    rb.setInterpolationWorldTransform(rb.getWorldTransform());
    rb.setLinearVelocity(toBt(twist.linear + twist.angular.cross(T.translation() - origin)));
    rb.setAngularVelocity(toBt(twist.angular));
    rb.clearForces();
    rb.activate(true);
  }
}

void PhysicsRobot::setBodyVelocities(const Twist3& twist) {
  for (Body& b : bodies_) {
    b.rigid->setLinearVelocity(toBt(twist.linear));
    b.rigid->setAngularVelocity(toBt(twist.angular));
    b.rigid->activate(true);
  }
}

void PhysicsRobot::wake() {
  for (Body& b : bodies_) b.rigid->activate(true);
}

Eigen::Isometry3d PhysicsRobot::T_world_body(size_t body) const {
  return toEigen(bodies_[body].rigid->getWorldTransform());
}

double PhysicsRobot::staticPenetrationM() const {
  double deepest_m = 0;
  btDispatcher* dispatcher = world_->getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    const bool ours_a = ownsBody(a), ours_b = ownsBody(b);
    if (!((ours_a && b->isStaticObject()) || (ours_b && a->isStaticObject()))) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      deepest_m = std::max(deepest_m, -double(manifold->getContactPoint(p).getDistance()));
    }
  }
  return deepest_m;
}

std::vector<BodyContact> PhysicsRobot::contacts(size_t body, double dt_s) const {
  return bodyContacts(*world_->getDispatcher(), bodies_.at(body).rigid.get(), dt_s);
}

int PhysicsRobot::bodyIndexOf(const btCollisionObject* object) const {
  for (size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].rigid.get() == object) return static_cast<int>(b);
  return -1;
}

bool PhysicsRobot::ownsBody(const btCollisionObject* object) const {
  for (const Body& body : bodies_)
    if (body.rigid.get() == object) return true;
  return false;
}

bool PhysicsRobot::hasLink(const std::string& link) const {
  return plan_.body_of_link.count(link) > 0;
}

Eigen::Isometry3d PhysicsRobot::linkPose(const std::string& link) const {
  const size_t b = plan_.body_of_link.at(link);
  return T_world_body(b) * bodies_[b].T_com_root * plan_.bodies[b].T_root_link.at(link);
}

Twist3 PhysicsRobot::linkTwist(const std::string& link) const {
  const size_t b = plan_.body_of_link.at(link);
  const btRigidBody& rb = *bodies_[b].rigid;
  Twist3 t;
  t.angular = toEigen(rb.getAngularVelocity());
  const Eigen::Vector3d r = linkPose(link).translation() - toEigen(rb.getCenterOfMassPosition());
  t.linear = toEigen(rb.getLinearVelocity()) + t.angular.cross(r);
  return t;
}

int PhysicsRobot::jointIndex(const std::string& name) const {
  for (size_t i = 0; i < plan_.joints.size(); ++i) {
    if (plan_.joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

btVector3 PhysicsRobot::jointAxisInWorld(size_t joint) const {
  const btHingeConstraint& h = *hinges_[joint];
  return h.getRigidBodyA().getWorldTransform().getBasis() * h.getAFrame().getBasis().getColumn(2);
}

double PhysicsRobot::jointVelocity(size_t joint) const {
  const btHingeConstraint& h = *hinges_[joint];
  return (h.getRigidBodyB().getAngularVelocity() - h.getRigidBodyA().getAngularVelocity())
      .dot(jointAxisInWorld(joint));
}

void PhysicsRobot::setJointPositions(const std::vector<double>& angles_rad) {
  // Bodies are planned depth first, so a body's parent body has a smaller index.
  std::vector<const JointPlan*> joint_of_body(bodies_.size(), nullptr);
  std::vector<double> angle_of_body(bodies_.size(), 0.0);
  for (size_t i = 0; i < plan_.joints.size(); ++i) {
    joint_of_body[plan_.joints[i].child_body] = &plan_.joints[i];
    angle_of_body[plan_.joints[i].child_body] = angles_rad.at(i);
  }
  std::vector<Eigen::Isometry3d> T_world_root(bodies_.size());
  T_world_root[0] = linkPose(plan_.bodies[0].root_link);
  for (size_t b = 1; b < bodies_.size(); ++b) {
    const JointPlan& j = *joint_of_body[b];
    T_world_root[b] = T_world_root[j.parent_body] * j.T_parentroot_joint *
                      Eigen::AngleAxisd(angle_of_body[b], j.axis);
  }
  for (size_t b = 0; b < bodies_.size(); ++b) {
    btRigidBody& rb = *bodies_[b].rigid;
    rb.setWorldTransform(toBt(T_world_root[b] * plan_.bodies[b].T_root_com));
    rb.setInterpolationWorldTransform(rb.getWorldTransform());
    rb.setLinearVelocity(btVector3(0, 0, 0));
    rb.setAngularVelocity(btVector3(0, 0, 0));
    rb.clearForces();
    rb.activate(true);
  }
  for (size_t i = 0; i < hinges_.size(); ++i) {
    joint_angles_[i] = angles_rad[i];
    last_raw_angles_[i] = hinges_[i]->getHingeAngle();
    motors_[i].reference_rad = angles_rad[i];
  }
}

void PhysicsRobot::setJointMotor(size_t joint, double velocity_radps, double max_torque_nm) {
  Motor& m = motors_[joint];
  if (!m.enabled) m.reference_rad = joint_angles_[joint];
  if (velocity_radps != 0 && !bodies_.front().rigid->isActive()) wake();
  m.enabled = true;
  m.velocity_radps = velocity_radps;
  m.max_torque_nm = max_torque_nm;
}

void PhysicsRobot::setBodyMass(size_t body, double mass_kg, const Eigen::Vector3d& principal) {
  btRigidBody& rb = *bodies_.at(body).rigid;
  rb.setMassProps(mass_kg, toBt(principal));
  rb.updateInertiaTensor();
  rb.activate(true);
  plan_.bodies[body].mass_kg = mass_kg;
  plan_.bodies[body].principal_inertia = principal;
}

void PhysicsRobot::setBodyGravity(size_t body, bool on) {
  btRigidBody& rb = *bodies_.at(body).rigid;
  // Flagged, the world's setGravity (and adding the body to another world) leaves it be.
  if (on) {
    rb.setFlags(rb.getFlags() & ~BT_DISABLE_WORLD_GRAVITY);
    rb.setGravity(world_->getGravity());
  } else {
    rb.setFlags(rb.getFlags() | BT_DISABLE_WORLD_GRAVITY);
    rb.setGravity(btVector3(0, 0, 0));
  }
  rb.activate(true);
}

void PhysicsRobot::setJointDamping(size_t joint, double damping_nms_per_rad) {
  damping_.at(joint) = damping_nms_per_rad;
}

void PhysicsRobot::setJointLimits(size_t joint, double lower_rad, double upper_rad) {
  hinges_.at(joint)->setLimit(lower_rad, upper_rad);
  plan_.joints[joint].limited = lower_rad <= upper_rad;
  plan_.joints[joint].lower = lower_rad;
  plan_.joints[joint].upper = upper_rad;
  wake();
}

void PhysicsRobot::setJointParam(size_t joint, int param, double value) {
  hinges_.at(joint)->setParam(param, static_cast<btScalar>(value), -1);
}

void PhysicsRobot::applyMotors(double dt_s) {
  for (size_t i = 0; i < damping_.size(); ++i) {
    if (damping_[i] == 0) continue;
    btHingeConstraint& h = *hinges_[i];
    if (!h.getRigidBodyA().isActive() && !h.getRigidBodyB().isActive()) continue;
    const btVector3 torque = jointAxisInWorld(i) * (-damping_[i] * jointVelocity(i));
    h.getRigidBodyB().applyTorque(torque);
    h.getRigidBodyA().applyTorque(-torque);
  }
  for (size_t i = 0; i < motors_.size(); ++i) {
    Motor& m = motors_[i];
    if (!m.enabled) continue;
    // Proportional pull towards the reference; the error is bounded so that a
    // stalled wheel (torque limit, wall) does not wind up and jump when freed.
    const double error = std::clamp(m.reference_rad - joint_angles_[i], -kMaxMotorLagRad,
                                    kMaxMotorLagRad);
    m.reference_rad = joint_angles_[i] + error + m.velocity_radps * dt_s;
    hinges_[i]->enableAngularMotor(true, m.velocity_radps + kMotorStiffnessPerS * error,
                                   m.max_torque_nm * dt_s);
  }
}

void PhysicsRobot::updateJointAngles() {
  for (size_t i = 0; i < hinges_.size(); ++i) {
    btHingeConstraint& h = *hinges_[i];
    const double raw = h.getHingeAngle();
    joint_angles_[i] += wrapToPi(raw - last_raw_angles_[i]);
    last_raw_angles_[i] = raw;
  }
}

}  // namespace bullet_sim
