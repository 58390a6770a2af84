#ifndef BULLET_SIM_CORE_PHYSICS_WORLD_H
#define BULLET_SIM_CORE_PHYSICS_WORLD_H

#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "bullet_sim/description/world_spec.h"

namespace bullet_sim {

/// The Bullet dynamics world with the static shapes of a WorldSpec. Parts of
/// one robot never collide with each other (Gazebo's self_collide false);
/// friction of a contact is the smaller of the two surfaces' (as ODE does).
class PhysicsWorld {
 public:
  explicit PhysicsWorld(const WorldSpec& spec);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  btDiscreteDynamicsWorld* dynamics() { return world_.get(); }
  const btDiscreteDynamicsWorld& dynamics() const { return *world_; }
  void step(double dt_s);

 private:
  struct RobotPairFilter : btOverlapFilterCallback {
    bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override;
  };
  RobotPairFilter filter_;
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PHYSICS_WORLD_H
