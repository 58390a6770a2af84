#ifndef BULLET_SIM_CORE_PHYSICS_WORLDS_H
#define BULLET_SIM_CORE_PHYSICS_WORLDS_H

#include <functional>
#include <map>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "bullet_sim/description/world_spec.h"
#include "physics/contact_groups.h"
#include "physics/physics_robot.h"
#include "physics/physics_world.h"
#include "physics/ray_scene.h"
#include "physics/step_pool.h"

namespace bullet_sim {

/// The robots' physics, in as many Bullet worlds as there are robots: each robot has a
/// home world (with the world's static shapes), and robots that may touch in the coming
/// steps (contact_groups.h) are simulated together in the home world of the one with the
/// smallest id; apart again, each goes back to its own. Robots in different worlds cannot
/// touch within those steps, so each world takes all of them on one thread of a StepPool
/// (its robots' own work between steps included, see RobotStepHooks), and the result is
/// the same to the bit whatever the number of threads. Rays are cast in a RayScene that
/// holds every robot.
/// What is done for each robot around each of its world's steps, on the thread that steps
/// the world: before(id, j) ahead of the j-th step of a PhysicsWorlds::step call (from 0),
/// after(id, j) once it is taken. Each touches robot `id`'s own state only.
struct RobotStepHooks {
  std::function<void(int id, unsigned j)> before, after;
};

class PhysicsWorlds {
 public:
  /// `threads` >= 1.
  PhysicsWorlds(const WorldSpec& spec, unsigned threads);
  ~PhysicsWorlds();
  PhysicsWorlds(const PhysicsWorlds&) = delete;
  PhysicsWorlds& operator=(const PhysicsWorlds&) = delete;

  /// A new home world for robot `id`, to build the robot in; then attach() it.
  btDiscreteDynamicsWorld* addHome(int id);
  void attach(int id, PhysicsRobot* robot);
  /// Before robot `id` is destroyed: the robots simulated in its home go back to their
  /// own, and rays no longer see it. Its home goes with dropHome() once it is destroyed.
  void detach(int id);
  void dropHome(int id);

  /// Groups the robots for `steps` steps of dt_s and steps every world that holds one
  /// that many times, calling `hooks` for its robots around each step.
  void step(double dt_s, unsigned steps, const RobotStepHooks& hooks);
  /// The scene for rays, every robot where it is now.
  btCollisionWorld& rayWorld();
  /// Calls cast(i, scene) for each i in [0, n) on the pool's threads, with rayWorld() as
  /// the scene: each call must only read it (no broadphase ray walk, see castScan).
  void castInParallel(size_t n, const std::function<void(size_t, btCollisionWorld&)>& cast);
  /// Calls work(i) for each i in [0, n) on the pool's threads: work beside the physics
  /// (camera frames), with a HelperChoice of its own.
  void runInParallel(size_t n, const std::function<void(size_t)>& work);
  void setGravity(const Eigen::Vector3d& gravity);
  /// Every world's solver, now and for the homes added later.
  void setSolver(const SolverSettings& settings);
  unsigned threads() const { return pool_.threads(); }

 private:
  struct Home {
    std::unique_ptr<PhysicsWorld> world;
    PhysicsRobot* robot = nullptr;  ///< null until attached, and after detach
    int group = 0;                  ///< the home (robot id) it is simulated in now
  };
  /// A world to step and the robots in it, by id.
  struct Busy {
    PhysicsWorld* world;
    std::vector<int> robots;
  };
  /// Puts each robot in the world of its contact group for the coming `horizon_s` of sim
  /// time and lists the worlds to step in busy_. A lone robot steps at home, its bounds
  /// unread.
  void regroup(double horizon_s);
  /// Puts members_[member] in the world of robot `group` for the coming steps, listing it
  /// with that world in busy_ (a robot in its own world makes that world busy: members come
  /// in id order, so a group's host comes before its guests).
  void moveTo(size_t member, int group);

  StaticShapes statics_;
  Eigen::Vector3d gravity_;
  SolverSettings solver_;
  std::map<int, Home> homes_;  ///< by robot id: the order of every pass over the robots
  RayScene rays_;
  StepPool pool_;
  HelperChoice scan_choice_;  ///< whether scans pay on the helpers, apart from the steps'
  HelperChoice other_choice_; ///< whether runInParallel's work pays on them
  std::vector<GroupMember> members_;  ///< the attached robots of the last regroup, by id
  std::vector<Home*> member_homes_;   ///< their homes
  std::vector<Busy> busy_;            ///< the worlds stepped in the last round, by host id
  size_t busy_count_ = 0;             ///< busy_'s first entries in use (the rest kept for reuse)
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_PHYSICS_WORLDS_H
