#include "physics/physics_worlds.h"

#include "physics/bullet_convert.h"

namespace bullet_sim {

PhysicsWorlds::PhysicsWorlds(const WorldSpec& spec, unsigned threads)
    : statics_(spec), gravity_(spec.gravity), rays_(statics_), pool_(threads) {}

PhysicsWorlds::~PhysicsWorlds() = default;

btDiscreteDynamicsWorld* PhysicsWorlds::addHome(int id) {
  Home& home = homes_[id];
  home.world = std::make_unique<PhysicsWorld>(statics_, gravity_);
  home.world->setSolver(solver_);
  home.robot = nullptr;
  return home.world->dynamics();
}

void PhysicsWorlds::attach(int id, PhysicsRobot* robot) {
  Home& home = homes_.at(id);
  home.robot = robot;
  home.group = id;
  rays_.addRobot(id, *robot);
}

void PhysicsWorlds::detach(int id) {
  for (auto& entry : homes_) {
    Home& guest = entry.second;
    if (entry.first != id && guest.robot && guest.group == id) {
      guest.robot->moveToWorld(guest.world->dynamics());
      guest.group = entry.first;
    }
  }
  homes_.at(id).robot = nullptr;
  rays_.removeRobot(id);
}

void PhysicsWorlds::dropHome(int id) { homes_.erase(id); }

void PhysicsWorlds::regroup(double horizon_s) {
  members_.clear();
  member_homes_.clear();
  for (auto& entry : homes_) {
    if (!entry.second.robot) continue;
    GroupMember m;
    m.id = entry.first;
    m.group = entry.second.group;
    members_.push_back(m);
    member_homes_.push_back(&entry.second);
  }
  busy_count_ = 0;
  if (members_.size() < 2) {
    // No two robots to group, and no bounds needed: a lone robot steps at home.
    for (size_t i = 0; i < members_.size(); ++i) moveTo(i, members_[i].id);
    return;
  }
  for (size_t i = 0; i < members_.size(); ++i) {
    GroupMember& m = members_[i];
    m.collides = member_homes_[i]->robot->bounds(&m.aabb_min, &m.aabb_max, &m.speed_mps);
  }
  const std::vector<int> groups = contactGroups(members_, horizon_s);
  for (size_t i = 0; i < members_.size(); ++i) moveTo(i, groups[i]);
}

void PhysicsWorlds::moveTo(size_t member, int group) {
  Home& home = *member_homes_[member];
  const int id = members_[member].id;
  const bool host = group == id;
  PhysicsWorld& world = host ? *home.world : *homes_.at(group).world;
  home.robot->moveToWorld(world.dynamics());
  home.group = group;
  if (host) {
    if (busy_count_ == busy_.size()) busy_.emplace_back();
    Busy& busy = busy_[busy_count_++];
    busy.world = &world;
    busy.robots.assign(1, id);
    return;
  }
  for (size_t i = busy_count_; i-- > 0;) {
    if (busy_[i].world == &world) {
      busy_[i].robots.push_back(id);
      return;
    }
  }
}

void PhysicsWorlds::step(double dt_s, unsigned steps, const RobotStepHooks& hooks) {
  regroup(dt_s * steps);
  const auto run_world = [this, dt_s, steps, &hooks](size_t i) {
    const Busy& busy = busy_[i];
    for (unsigned j = 0; j < steps; ++j) {
      for (int id : busy.robots) hooks.before(id, j);
      busy.world->step(dt_s);
      for (int id : busy.robots) hooks.after(id, j);
    }
  };
  if (busy_count_ == 1) {
    run_world(0);  // one world: no job for the pool
    return;
  }
  pool_.run(busy_count_, run_world, steps);
}

btCollisionWorld& PhysicsWorlds::rayWorld() {
  // Teleports and joint settings move bodies between steps too; a sync is a few
  // bounding boxes per robot.
  rays_.sync();
  return rays_.world();
}

void PhysicsWorlds::castInParallel(size_t n,
                                   const std::function<void(size_t, btCollisionWorld&)>& cast) {
  btCollisionWorld& scene = rayWorld();
  pool_.run(n, [&cast, &scene](size_t i) { cast(i, scene); }, 1, &scan_choice_);
}

void PhysicsWorlds::runInParallel(size_t n, const std::function<void(size_t)>& work) {
  pool_.run(n, work, 1, &other_choice_);
}

void PhysicsWorlds::setSolver(const SolverSettings& settings) {
  solver_ = settings;
  for (auto& entry : homes_) entry.second.world->setSolver(settings);
}

void PhysicsWorlds::setGravity(const Eigen::Vector3d& gravity) {
  gravity_ = gravity;
  for (auto& entry : homes_) entry.second.world->dynamics()->setGravity(toBt(gravity));
}

}  // namespace bullet_sim
