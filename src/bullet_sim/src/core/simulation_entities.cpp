// Simulation: models, links and joints by name, external forces, physics settings.
#include <stdexcept>

#include "description/robot_plan.h"
#include "physics/bullet_convert.h"
#include "simulation_impl.h"

namespace bullet_sim {
namespace {

const std::string& checkLink(const PhysicsRobot& robot, const std::string& robot_name,
                               const std::string& link) {
  if (!robot.hasLink(link)) {
    throw std::out_of_range("model '" + robot_name + "' has no link '" + link + "'");
  }
  return link;
}

size_t checkJoint(const PhysicsRobot& robot, const std::string& robot_name,
                    const std::string& joint) {
  const int index = robot.jointIndex(joint);
  if (index < 0) {
    throw std::out_of_range("model '" + robot_name + "' has no movable joint '" + joint + "'");
  }
  return static_cast<size_t>(index);
}

}  // namespace

void Simulation::Impl::applyExternalForces() {
  if (forces.wrenchCount() == 0 && forces.effortCount() == 0) return;
  const double now_s = timeAtStep(steps);
  for (const BodyWrench& w : forces.wrenchesAt(now_s)) {
    const auto it = robots.find(w.robot);
    if (it != robots.end() && it->second->physics->hasLink(w.link)) {
      it->second->physics->applyLinkWrench(w.link, w.wrench);
    }
  }
  for (const JointEffort& e : forces.effortsAt(now_s)) {
    const auto it = robots.find(e.robot);
    if (it == robots.end()) continue;
    const int joint = it->second->physics->jointIndex(e.joint);
    if (joint >= 0) it->second->physics->applyJointEffort(static_cast<size_t>(joint), e.effort);
  }
}

std::optional<EntityName> Simulation::findEntity(const std::string& name) const {
  std::optional<EntityName> entity = splitEntityName(name, robotNames());
  if (entity && !entity->link.empty() && !impl_->robot(entity->model).physics->hasLink(entity->link)) {
    return std::nullopt;
  }
  return entity;
}

EntityState Simulation::entityState(const EntityName& entity) const {
  if (!entity.link.empty()) return linkState(entity.model, entity.link);
  // A model is its model frame (an SDF model's root link may sit elsewhere in it).
  return EntityState{modelPose(entity.model), modelTwist(entity.model)};
}

std::optional<EntityState> Simulation::frameState(const std::string& name) const {
  if (isWorldFrameName(name)) return EntityState{};
  if (const std::optional<EntityName> entity = findEntity(name)) return entityState(*entity);
  for (const StaticModel& model : impl_->world.static_models) {
    if (model.name == name) return EntityState{model.pose, Twist3{}};
  }
  // gazebo_ros reads these as the world too (it has no map frame), after the entities.
  if (name == "map" || name == "/map") return EntityState{};
  return std::nullopt;
}

std::vector<std::string> Simulation::linkNames(const std::string& robot) const {
  std::vector<std::string> names;
  for (const auto& link : impl_->robot(robot).physics->plan().body_of_link) {
    names.push_back(link.first);
  }
  return names;
}

std::string Simulation::rootLink(const std::string& robot) const {
  return impl_->robot(robot).physics->plan().bodies[0].root_link;
}

EntityState Simulation::linkState(const std::string& robot, const std::string& link) const {
  const PhysicsRobot& physics = *impl_->robot(robot).physics;
  checkLink(physics, robot, link);
  return {toPose3(physics.linkPose(link)), physics.linkTwist(link)};
}

void Simulation::setLinkState(const std::string& robot, const std::string& link,
                              const Pose3& pose, const Twist3& twist) {
  Impl::Robot& r = impl_->robot(robot);
  checkLink(*r.physics, robot, link);
  const std::string root = rootLink(robot);
  const Eigen::Isometry3d T_link_root = r.physics->linkPose(link).inverse() * r.physics->linkPose(root);
  const Eigen::Isometry3d T_world_root = toIsometry(pose) * T_link_root;
  Twist3 root_twist = twist;
  root_twist.linear += twist.angular.cross(T_world_root.translation() - pose.position);
  r.physics->moveRoot(T_world_root, root_twist);
  for (ImuSensor& imu : r.imus) imu.reset();
}

std::optional<EntityName> Simulation::findJoint(const std::string& name) const {
  const std::vector<std::string> models = robotNames();
  if (std::optional<EntityName> scoped = splitEntityName(name, models)) {
    if (!scoped->link.empty() && impl_->robot(scoped->model).physics->jointIndex(scoped->link) >= 0)
      return scoped;
  }
  for (const std::string& model : models) {
    if (impl_->robot(model).physics->jointIndex(name) >= 0) return EntityName{model, name};
  }
  return std::nullopt;
}

std::vector<std::string> Simulation::jointNames(const std::string& robot) const {
  std::vector<std::string> names;
  for (const JointPlan& j : impl_->robot(robot).physics->plan().joints) names.push_back(j.name);
  return names;
}

double Simulation::jointPosition(const std::string& robot, const std::string& joint) const {
  const PhysicsRobot& physics = *impl_->robot(robot).physics;
  return physics.jointPosition(checkJoint(physics, robot, joint));
}

double Simulation::jointVelocity(const std::string& robot, const std::string& joint) const {
  const PhysicsRobot& physics = *impl_->robot(robot).physics;
  return physics.jointVelocity(checkJoint(physics, robot, joint));
}

void Simulation::setJointPositions(const std::string& robot,
                                   const std::map<std::string, double>& positions) {
  PhysicsRobot& physics = *impl_->robot(robot).physics;
  std::vector<double> angles;
  for (size_t i = 0; i < physics.plan().joints.size(); ++i) {
    angles.push_back(physics.jointPosition(i));
  }
  for (const auto& p : positions) angles[checkJoint(physics, robot, p.first)] = p.second;
  physics.setJointPositions(angles);
  for (ImuSensor& imu : impl_->robot(robot).imus) imu.reset();
}

ExternalForces& Simulation::externalForces() { return impl_->forces; }

double Simulation::physicsStepS() const { return impl_->cfg.physics_step_s; }

void Simulation::setPhysicsStep(double step_s) {
  if (!(step_s > 0)) {
    throw std::invalid_argument("physics step must be > 0 s, got " + std::to_string(step_s));
  }
  impl_->epoch_s = timeS();
  impl_->steps = 0;
  impl_->cfg.physics_step_s = step_s;
  for (auto& r : impl_->robots) r.second->schedule.restart();  // phases count from here
}

Eigen::Vector3d Simulation::gravity() const { return impl_->world.gravity; }

void Simulation::setGravity(const Eigen::Vector3d& gravity_mps2) {
  impl_->world.gravity = gravity_mps2;
  impl_->physics->setGravity(gravity_mps2);
  for (auto& r : impl_->robots) r.second->physics->wake();
}

}  // namespace bullet_sim
