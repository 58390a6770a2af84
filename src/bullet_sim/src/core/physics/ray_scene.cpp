#include "physics/ray_scene.h"

namespace bullet_sim {
namespace {

/// Rays need no contact manifolds: the scene never runs collision detection.
constexpr int kNoContacts = 1;

}  // namespace

RayScene::RayScene(const StaticShapes& statics)
    : backend_(std::make_unique<CollisionBackend>(kNoContacts)),
      world_(std::make_unique<btCollisionWorld>(&backend_->dispatcher, &backend_->broadphase,
                                                &backend_->config)),
      statics_(addStaticObjects(statics, world_.get())) {}

RayScene::~RayScene() {
  for (auto& robot : robots_) {
    for (StandIn& s : robot.second) world_->removeCollisionObject(s.object.get());
  }
  for (auto& obj : statics_) world_->removeCollisionObject(obj.get());
}

void RayScene::addRobot(int id, const PhysicsRobot& robot) {
  std::vector<StandIn>& stand_ins = robots_[id];
  for (const btRigidBody* body : robot.collidingBodies()) {
    auto obj = std::make_unique<btCollisionObject>();
    obj->setCollisionShape(const_cast<btCollisionShape*>(body->getCollisionShape()));
    obj->setWorldTransform(body->getWorldTransform());
    obj->setUserIndex(id);
    world_->addCollisionObject(obj.get(), btBroadphaseProxy::DefaultFilter,
                               btBroadphaseProxy::AllFilter);
    stand_ins.push_back({body, std::move(obj)});
  }
}

void RayScene::removeRobot(int id) {
  const auto it = robots_.find(id);
  if (it == robots_.end()) return;
  for (StandIn& s : it->second) world_->removeCollisionObject(s.object.get());
  robots_.erase(it);
}

void RayScene::sync() {
  for (auto& robot : robots_) {
    for (StandIn& s : robot.second) {
      // Sensors of many robots read in one step: each body's box is updated once.
      if (s.object->getWorldTransform() == s.body->getWorldTransform()) continue;
      s.object->setWorldTransform(s.body->getWorldTransform());
      world_->updateSingleAabb(s.object.get());
    }
  }
}

}  // namespace bullet_sim
