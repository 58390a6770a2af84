#include "physics/physics_world.h"

#include <algorithm>

#include "description/robot_plan.h"
#include "physics/bullet_convert.h"
#include "physics/collision_shapes.h"
#include "physics/physics_robot.h"

namespace bullet_sim {
namespace {

/// The friction of the surface a contact touches. A compound body's parts keep their own
/// links' friction: Bullet hands a contact with a part the part's wrapper, whose index is
/// the part's. Any other body (a single shape, a static shape) has one friction, its own.
/// (The part indices Bullet passes beside the wrappers are set only for compounds and
/// meshes; for two single shapes they are left as they were.)
double frictionOf(const btCollisionObjectWrapper* w) {
  const btCollisionObject* obj = w->getCollisionObject();
  const auto* material = static_cast<const BodyMaterial*>(obj->getUserPointer());
  if ((obj->getCollisionFlags() & btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK) && material &&
      obj->getCollisionShape()->isCompound() && w->m_index >= 0 &&
      w->m_index < static_cast<int>(material->child_friction.size())) {
    return material->child_friction[w->m_index];
  }
  return obj->getFriction();
}

/// Gazebo's ODE takes the smaller of the two surfaces' coefficients for a contact; Bullet
/// would multiply them.
bool combineFriction(btManifoldPoint& cp, const btCollisionObjectWrapper* a, int, int,
                     const btCollisionObjectWrapper* b, int, int) {
  cp.m_combinedFriction = std::min(frictionOf(a), frictionOf(b));
  return true;
}

/// Contacts a robot's home world keeps ready: a Burger on the round track has about ten.
constexpr int kWorldPoolSize = 256;

btDefaultCollisionConstructionInfo poolOf(int pool_size) {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = pool_size;
  info.m_defaultMaxCollisionAlgorithmPoolSize = pool_size;
  return info;
}

}  // namespace

bool closesFasterThan(const btPersistentManifold& manifold, double speed_mps) {
  const btRigidBody* a = btRigidBody::upcast(manifold.getBody0());
  const btRigidBody* b = btRigidBody::upcast(manifold.getBody1());
  for (int i = 0; i < manifold.getNumContacts(); ++i) {
    const btManifoldPoint& cp = manifold.getContactPoint(i);
    if (cp.getDistance() > manifold.getContactProcessingThreshold()) continue;
    btVector3 v(0, 0, 0);
    if (a) v += a->getVelocityInLocalPoint(cp.getPositionWorldOnA() - a->getCenterOfMassPosition());
    if (b) v -= b->getVelocityInLocalPoint(cp.getPositionWorldOnB() - b->getCenterOfMassPosition());
    // The normal points from B to A: A approaching B moves against it.
    if (-v.dot(cp.m_normalWorldOnB) > speed_mps) return true;
  }
  return false;
}

std::vector<std::pair<btManifoldPoint*, btScalar>> capPushOut(btDispatcher* dispatcher, double erp,
                                                               double dt_s, double max_vel_mps) {
  std::vector<std::pair<btManifoldPoint*, btScalar>> capped;
  if (!(erp > 0) || !(dt_s > 0)) return capped;
  const btScalar min_distance = static_cast<btScalar>(-max_vel_mps * dt_s / erp);
  for (int i = 0; i < dispatcher->getNumManifolds(); ++i) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(i);
    for (int j = 0; j < manifold->getNumContacts(); ++j) {
      btManifoldPoint& cp = manifold->getContactPoint(j);
      if (cp.m_distance1 < min_distance) {
        capped.emplace_back(&cp, cp.m_distance1);
        cp.m_distance1 = min_distance;
      }
    }
  }
  return capped;
}

void restoreDepths(const std::vector<std::pair<btManifoldPoint*, btScalar>>& capped) {
  for (const auto& [cp, distance] : capped) cp->m_distance1 = distance;
}

void ImpactAwareWorld::solveConstraints(btContactSolverInfo& info) {
  bool impact = false;
  btDispatcher* dispatcher = getDispatcher();
  for (int i = 0; i < dispatcher->getNumManifolds() && !impact; ++i) {
    impact = closesFasterThan(*dispatcher->getManifoldByIndexInternal(i), kImpactApproachMps);
  }
  // The step after an impact starts from its impulses (warm starting): it needs as many
  // iterations to take them back, or they throw the body up.
  steps_since_impact_ = impact ? 0 : std::min(steps_since_impact_ + 1, kStepsAfterImpact + 1);
  info.m_numIterations = steps_since_impact_ <= kStepsAfterImpact
                             ? std::max(kImpactIterations, iterations_)
                             : iterations_;
  // The solver reads the depths once, to set up its contacts; contact sensors read them after
  // the step, as found.
  const auto capped = capPushOut(dispatcher, info.m_erp, info.m_timeStep, kContactMaxVelMps);
  btDiscreteDynamicsWorld::solveConstraints(info);
  restoreDepths(capped);
}

CollisionBackend::CollisionBackend(int pool_size) : config(poolOf(pool_size)) {}

bool PhysicsWorld::RobotPairFilter::needBroadphaseCollision(btBroadphaseProxy* a,
                                                            btBroadphaseProxy* b) const {
  if (!(a->m_collisionFilterGroup & b->m_collisionFilterMask) ||
      !(b->m_collisionFilterGroup & a->m_collisionFilterMask)) {
    return false;
  }
  const auto* oa = static_cast<const btCollisionObject*>(a->m_clientObject);
  const auto* ob = static_cast<const btCollisionObject*>(b->m_clientObject);
  return oa->getUserIndex() < 0 || oa->getUserIndex() != ob->getUserIndex();
}

StaticShapes::StaticShapes(const WorldSpec& spec) {
  for (size_t i = 0; i < spec.shapes.size(); ++i) {
    const StaticShape& s = spec.shapes[i];
    if (!s.collides) continue;
    shapes_.push_back(makeCollisionShape(s, s.mesh.get(), Motion::Static));
    placed_.push_back({shapes_.back().get(), toBt(toIsometry(s.pose)), s.friction, i});
  }
}

std::vector<std::unique_ptr<btCollisionObject>> addStaticObjects(const StaticShapes& statics,
                                                                 btCollisionWorld* world) {
  std::vector<std::unique_ptr<btCollisionObject>> objects;
  for (const StaticShapes::Placed& s : statics.placed()) {
    auto obj = std::make_unique<btCollisionObject>();
    obj->setCollisionShape(s.shape);
    obj->setWorldTransform(s.pose);
    obj->setFriction(s.friction);
    obj->setUserIndex(-1);
    obj->setUserIndex2(static_cast<int>(s.shape_index));
    // Bullet recomputes the bounding box of every "active" object each step;
    // static shapes never move.
    obj->setActivationState(ISLAND_SLEEPING);
    world->addCollisionObject(obj.get(), btBroadphaseProxy::StaticFilter,
                              btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    objects.push_back(std::move(obj));
  }
  return objects;
}

PhysicsWorld::PhysicsWorld(const StaticShapes& statics, const Eigen::Vector3d& gravity)
    : backend_(std::make_unique<CollisionBackend>(kWorldPoolSize)),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<ImpactAwareWorld>(&backend_->dispatcher,
                                                        &backend_->broadphase, solver_.get(),
                                                        &backend_->config)) {
  gContactAddedCallback = combineFriction;
  world_->getPairCache()->setOverlapFilterCallback(&filter_);
  world_->setGravity(toBt(gravity));
  world_->setForceUpdateAllAabbs(false);
  objects_ = addStaticObjects(statics, world_.get());
}

PhysicsWorld::~PhysicsWorld() {
  for (auto& obj : objects_) world_->removeCollisionObject(obj.get());
}

void PhysicsWorld::setSolver(const SolverSettings& settings) {
  btContactSolverInfo& info = world_->getSolverInfo();
  world_->setIterations(settings.iterations);
  info.m_numIterations = settings.iterations;
  info.m_sor = static_cast<btScalar>(settings.sor);
  info.m_erp = static_cast<btScalar>(settings.erp);
  info.m_globalCfm = static_cast<btScalar>(settings.cfm);
}

void PhysicsWorld::step(double dt_s) { world_->stepSimulation(dt_s, 0, dt_s); }

}  // namespace bullet_sim
