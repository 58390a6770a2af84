#ifndef BULLET_SIM_CORE_PHYSICS_WORLD_H
#define BULLET_SIM_CORE_PHYSICS_WORLD_H

#include <memory>
#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <Eigen/Core>

#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/types.h"

namespace bullet_sim {

/// The collision shapes of a WorldSpec's static shapes, made once and shared by every world
/// that holds them (a shape is only read while a world steps or a ray is cast).
class StaticShapes {
 public:
  struct Placed {
    btCollisionShape* shape;
    btTransform pose;
    double friction;
    size_t shape_index;  ///< into WorldSpec::shapes; also the object's Bullet user index 2
  };
  explicit StaticShapes(const WorldSpec& spec);
  const std::vector<Placed>& placed() const { return placed_; }

 private:
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<Placed> placed_;
};

/// What a Bullet collision world works with besides its objects: configuration, dispatcher
/// and broadphase (the world keeps pointers to them, so they do not move). The configuration
/// keeps `pool_size` contact manifolds and collision algorithms ready (Bullet's default,
/// 4096 of each, is 4.5 MB, and there is a world per robot); more come from the heap.
struct CollisionBackend {
  explicit CollisionBackend(int pool_size);
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
};

/// Adds a static collision object for every shape of `statics` to `world`, as a world's
/// walls and ground: they never move and do not collide with each other.
std::vector<std::unique_ptr<btCollisionObject>> addStaticObjects(const StaticShapes& statics,
                                                                 btCollisionWorld* world);

/// Solver iterations of a step in which a contact closes faster than kImpactApproachMps
/// (a body dropped from 1.3 cm or more lands, or hits something hard), and of any other step.
/// Bullet's sequential impulses pass an impact on a 28 g wheel to the 0.9 kg body it hangs
/// from a few percent per iteration, while a contact on the body itself (the Burger's
/// caster) stops it at once: 10 iterations leave the body pitching at up to 8 rad/s and
/// bouncing at 0.5 m/s after a 0.2 m drop. Gazebo's ODE runs 50 iterations of SOR 1.3 at
/// every step; here the extra iterations go only to the steps that need them.
constexpr int kSolverIterations = 10;
constexpr int kImpactIterations = 100;
constexpr double kImpactApproachMps = 0.5;
constexpr int kStepsAfterImpact = 3;

/// Gazebo's ODE pushes overlapping bodies apart at erp x depth / dt, but no faster than the
/// contact's max_vel: the body's surface `<contact><ode><max_vel>` (SDF default 0.01 m/s),
/// truncated by the world's contact_max_correcting_vel (default 100). Bullet's contacts push
/// apart at erp x depth / dt uncapped (its split impulse only takes over past 4 cm), so a box
/// placed 6.8 mm inside a wall would leave it at 1.4 m/s. The surface's own max_vel is not
/// read: every contact gets the default.
constexpr double kContactMaxVelMps = 0.01;

/// Caps the penetration of every contact of `dispatcher` at the depth whose Baumgarte push-out
/// (`erp` x depth / `dt_s`) is `max_vel_mps`; returns the contacts changed with their depths,
/// for restoreDepths.
std::vector<std::pair<btManifoldPoint*, btScalar>> capPushOut(btDispatcher* dispatcher, double erp,
                                                               double dt_s, double max_vel_mps);
void restoreDepths(const std::vector<std::pair<btManifoldPoint*, btScalar>>& capped);

/// A contact of `manifold` whose two bodies close faster than `speed_mps` along its normal.
bool closesFasterThan(const btPersistentManifold& manifold, double speed_mps);

/// btDiscreteDynamicsWorld that gives a step with an impact (closesFasterThan
/// kImpactApproachMps), and the kStepsAfterImpact steps after it, at least
/// kImpactIterations solver iterations, any other the iterations set (kSolverIterations
/// unless set_physics_properties changed them). Contacts push overlapping bodies apart no
/// faster than kContactMaxVelMps (capPushOut), as ODE's max_vel.
class ImpactAwareWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
  void setIterations(int iterations) { iterations_ = iterations; }

 protected:
  void solveConstraints(btContactSolverInfo& info) override;

 private:
  int steps_since_impact_ = kStepsAfterImpact + 1;
  int iterations_ = kSolverIterations;
};

/// A Bullet dynamics world with the static shapes of a world. Parts of one robot never
/// collide with each other (Gazebo's self_collide false); friction of a contact is the
/// smaller of the two surfaces' (as ODE does); steps with an impact solve longer
/// (ImpactAwareWorld).
class PhysicsWorld {
 public:
  PhysicsWorld(const StaticShapes& statics, const Eigen::Vector3d& gravity);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  btDiscreteDynamicsWorld* dynamics() { return world_.get(); }
  const btDiscreteDynamicsWorld& dynamics() const { return *world_; }
  void step(double dt_s);
  void setSolver(const SolverSettings& settings);

 private:
  struct RobotPairFilter : btOverlapFilterCallback {
    bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override;
  };
  RobotPairFilter filter_;
  std::unique_ptr<CollisionBackend> backend_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<ImpactAwareWorld> world_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PHYSICS_WORLD_H
