#include "physics_world.h"

#include <algorithm>

#include "bullet_convert.h"
#include "collision_shapes.h"
#include "physics_robot.h"
#include "robot_plan.h"

namespace bullet_sim {
namespace {

constexpr double kStaticFriction = 1.0;

double frictionOf(const btCollisionObjectWrapper* w, int child_index) {
  const btCollisionObject* obj = w->getCollisionObject();
  const auto* material = static_cast<const BodyMaterial*>(obj->getUserPointer());
  if ((obj->getCollisionFlags() & btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK) && material &&
      child_index >= 0 && child_index < static_cast<int>(material->child_friction.size())) {
    return material->child_friction[child_index];
  }
  return obj->getFriction();
}

bool combineFriction(btManifoldPoint& cp, const btCollisionObjectWrapper* a, int, int index_a,
                     const btCollisionObjectWrapper* b, int, int index_b) {
  cp.m_combinedFriction = std::min(frictionOf(a, index_a), frictionOf(b, index_b));
  return true;
}

}  // namespace

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

PhysicsWorld::PhysicsWorld(const WorldSpec& spec)
    : config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                        solver_.get(), config_.get())) {
  gContactAddedCallback = combineFriction;
  world_->getPairCache()->setOverlapFilterCallback(&filter_);
  world_->setGravity(toBt(spec.gravity));
  world_->setForceUpdateAllAabbs(false);
  for (const StaticShape& s : spec.shapes) {
    if (!s.collides) continue;
    shapes_.push_back(makeCollisionShape(s, s.mesh.get(), Motion::Static));
    auto obj = std::make_unique<btCollisionObject>();
    obj->setCollisionShape(shapes_.back().get());
    obj->setWorldTransform(toBt(toIsometry(s.pose)));
    obj->setFriction(kStaticFriction);
    obj->setUserIndex(-1);
    // Bullet recomputes the bounding box of every "active" object each step;
    // static shapes never move.
    obj->setActivationState(ISLAND_SLEEPING);
    world_->addCollisionObject(obj.get(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    objects_.push_back(std::move(obj));
  }
}

PhysicsWorld::~PhysicsWorld() {
  for (auto& obj : objects_) world_->removeCollisionObject(obj.get());
}

void PhysicsWorld::step(double dt_s) { world_->stepSimulation(dt_s, 0, dt_s); }

}  // namespace bullet_sim
