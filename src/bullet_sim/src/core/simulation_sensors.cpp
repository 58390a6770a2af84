// Simulation's range sensors, block lasers and bumpers (Gazebo's libgazebo_ros_range.so,
// libgazebo_ros_block_laser.so and libgazebo_ros_bumper.so).

#include <map>
#include <random>

#include "bullet_sim/errors.h"
#include "description/robot_plan.h"
#include "sensors/ray_cone.h"
#include "simulation_impl.h"

namespace bullet_sim {
namespace {

void requireSensorLink(const PhysicsRobot& robot, const std::string& robot_name,
                       const std::string& what, const std::string& link) {
  if (!robot.hasLink(link)) {
    throw LoadError("robot '" + robot_name + "': " + what + " names link '" + link +
                    "' that does not exist");
  }
}

/// The name a collision goes by in messages: its SDF name, or for a URDF collision
/// (which has none, as a rule) the one Gazebo gives it.
const std::string& shownName(const CollisionPlan& c) {
  return c.name.empty() ? c.gazebo_name : c.name;
}

/// The reading of a range sensor or block laser `spec` on `robot` at sim time `time_s`:
/// its cone of rays cast in `ray_world` from where its link is now, made a reading by
/// `make` (rangeReading, blockLaserCloud) with the noise drawn from `rng`.
template <class Spec, class Make>
auto readRayCone(const PhysicsRobot& robot, const Spec& spec, std::mt19937_64* rng,
                 btCollisionWorld& ray_world, double time_s, Make make) {
  const Eigen::Isometry3d T_world_sensor =
      robot.linkPose(spec.link) * toIsometry(spec.pose_in_link);
  auto data = make(spec, castRayCone(ray_world, T_world_sensor, spec.rays), rng);
  data.time_s = time_s;
  return data;
}

}  // namespace

void Simulation::Impl::equipContactAndConeSensors(const std::string& name, Robot* r) {
  const RobotSpec& spec = r->spec;
  const PhysicsRobot& physics = *r->physics;
  for (const RangeSpec& s : spec.ranges) {
    requireSensorLink(physics, name, "range sensor '" + s.name + "'", s.link);
  }
  for (const BlockLaserSpec& s : spec.block_lasers) {
    requireSensorLink(physics, name, "block laser '" + s.name + "'", s.link);
  }
  r->bumpers.clear();
  for (const BumperSpec& s : spec.bumpers) {
    const std::string what = "bumper '" + s.name + "'";
    requireSensorLink(physics, name, what, s.link);
    const size_t body = physics.plan().body_of_link.at(s.link);
    const BodyPlan& plan = physics.plan().bodies[body];
    std::string known;
    for (size_t part = 0; part < plan.collisions.size(); ++part) {
      const CollisionPlan& c = plan.collisions[part];
      if (c.link == s.link) known += (known.empty() ? "'" : ", '") + shownName(c) + "'";
      if (c.link != s.link || (s.collision != c.gazebo_name && s.collision != c.name)) continue;
      r->bumpers.push_back({body, part, name + "::" + plan.root_link + "::" + shownName(c)});
      break;
    }
    if (r->bumpers.size() != static_cast<size_t>(&s - spec.bumpers.data()) + 1) {
      throw LoadError("robot '" + name + "': " + what + " <contact><collision> '" + s.collision +
                      "' is not a collision of link '" + s.link + "' (" +
                      (known.empty() ? "it has none" : "it has " + known) + ")");
    }
  }
}

std::string Simulation::Impl::collisionName(const btCollisionObject* object, int part) const {
  const int id = object->getUserIndex();
  if (id < 0) {
    const size_t shape = static_cast<size_t>(object->getUserIndex2());
    if (shape >= world.shapes.size()) return "";
    const StaticShape& s = world.shapes[shape];
    return s.model + "::" + s.link + "::" + s.name;
  }
  if (static_cast<size_t>(id) >= by_id.size() || !by_id[id]) return "";
  const Robot& other = *by_id[id];
  const int body = other.physics->bodyIndexOf(object);
  if (body < 0) return "";
  const BodyPlan& plan = other.physics->plan().bodies[body];
  if (part < 0 || static_cast<size_t>(part) >= plan.collisions.size()) return "";
  std::string model;
  for (const auto& entry : robots) {
    if (entry.second.get() == &other) model = entry.first;
  }
  return model + "::" + plan.root_link + "::" + shownName(plan.collisions[part]);
}

RangeData Simulation::readRange(const std::string& robot, size_t index) {
  Impl::Robot& r = impl_->robot(robot);
  return readRayCone(*r.physics, r.spec.ranges.at(index), &r.range_rngs.at(index),
                     impl_->physics->rayWorld(), timeS(), rangeReading);
}

BlockLaserCloudData Simulation::readBlockLaser(const std::string& robot, size_t index) {
  Impl::Robot& r = impl_->robot(robot);
  return readRayCone(*r.physics, r.spec.block_lasers.at(index), &r.block_laser_rngs.at(index),
                     impl_->physics->rayWorld(), timeS(), blockLaserCloud);
}

ContactsData Simulation::readBumper(const std::string& robot, size_t index) const {
  const Impl::Robot& r = impl_->robot(robot);
  const BumperSpec& spec = r.spec.bumpers.at(index);
  const Impl::Robot::BumperTarget& target = r.bumpers.at(index);
  ContactsData data;
  data.time_s = timeS();
  data.frame_id = spec.frame_id;
  // Forces and torques in the axes of the collision's link (the body's root link), as
  // Gazebo's ODE hands them out.
  const Eigen::Matrix3d R_link_world =
      r.physics->linkPose(r.physics->plan().bodies[target.body].root_link).linear().transpose();
  std::map<std::string, size_t> state_of;  // by the other collision's name
  for (const BodyContact& c : r.physics->contacts(target.body, impl_->cfg.physics_step_s)) {
    if (static_cast<size_t>(c.part) != target.part) continue;
    const std::string other = impl_->collisionName(c.other, c.other_part);
    auto found = state_of.find(other);
    if (found == state_of.end()) {
      found = state_of.emplace(other, data.states.size()).first;
      data.states.emplace_back();
      data.states.back().collision1_name = target.name;
      data.states.back().collision2_name = other;
    }
    ContactStateData& state = data.states[found->second];
    state.forces.push_back(R_link_world * c.force_n);
    state.torques.push_back(R_link_world * c.torque_nm);
    state.total_force += state.forces.back();
    state.total_torque += state.torques.back();
    state.positions.push_back(c.position_m);
    state.normals.push_back(c.normal);
    state.depths.push_back(c.depth_m);
  }
  return data;
}

}  // namespace bullet_sim
