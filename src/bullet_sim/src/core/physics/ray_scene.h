#ifndef BULLET_SIM_CORE_RAY_SCENE_H
#define BULLET_SIM_CORE_RAY_SCENE_H

#include <map>
#include <memory>
#include <vector>

#include <btBulletCollisionCommon.h>

#include "physics/physics_robot.h"
#include "physics/physics_world.h"

namespace bullet_sim {

/// The collision world that sensors cast their rays in: the world's static shapes and a
/// stand-in for every colliding body of every robot (same shape, same pose, same filter
/// group), whichever dynamics world the robot is simulated in. Robots are kept in the
/// order of their ids, so the scene is built the same way whatever stepped the robots.
class RayScene {
 public:
  explicit RayScene(const StaticShapes& statics);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  void addRobot(int id, const PhysicsRobot& robot);
  void removeRobot(int id);
  /// Puts every stand-in where its body is now (those of bodies that moved since the last
  /// sync).
  void sync();
  btCollisionWorld& world() { return *world_; }

 private:
  struct StandIn {
    const btRigidBody* body;
    std::unique_ptr<btCollisionObject> object;
  };
  std::unique_ptr<CollisionBackend> backend_;
  std::unique_ptr<btCollisionWorld> world_;
  std::vector<std::unique_ptr<btCollisionObject>> statics_;
  std::map<int, std::vector<StandIn>> robots_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_RAY_SCENE_H
