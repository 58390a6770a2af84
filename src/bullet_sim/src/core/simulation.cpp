#include "bullet_sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "bullet_sim/errors.h"
#include "description/robot_plan.h"
#include "physics/bullet_convert.h"
#include "sensors/ray_sensor.h"
#include "simulation_impl.h"

namespace bullet_sim {

namespace {

void requireLink(const PhysicsRobot& robot, const std::string& robot_name, const std::string& what,
                 const std::string& link) {
  if (!robot.hasLink(link)) {
    throw LoadError("robot '" + robot_name + "': " + what + " names link '" + link +
                    "' that does not exist");
  }
}

size_t requireHinge(const PhysicsRobot& robot, const std::string& robot_name,
                    const std::string& plugin, const std::string& tag, const std::string& joint) {
  const int index = robot.jointIndex(joint);
  if (index < 0) {
    throw LoadError("robot '" + robot_name + "': " + plugin + " <" + tag +
                    "> names joint '" + joint +
                    "' that does not exist (or is not revolute/continuous)");
  }
  return static_cast<size_t>(index);
}

/// A wheel joint's <limit velocity> in rad/s; continuous joints may declare one, and 0
/// (urdfdom's value when none is written) means no limit.
double wheelSpeedLimit(const RobotSpec& spec, const std::string& joint) {
  const urdf::JointConstSharedPtr j = spec.urdf->getJoint(joint);
  if (j && j->limits && j->limits->velocity > 0) return j->limits->velocity;
  return std::numeric_limits<double>::infinity();
}

/// One side's wheel joints of a drive (a skid steer's front and rear; a joint named twice
/// is driven once) and the lowest velocity limit among them.
struct DriveSide {
  std::vector<size_t> joints;
  double max_radps = std::numeric_limits<double>::infinity();
};

DriveSide driveSide(const PhysicsRobot& robot, const RobotSpec& spec, const std::string& name,
                    const std::vector<std::pair<const char*, std::string>>& tagged_joints) {
  DriveSide side;
  for (const auto& tagged : tagged_joints) {
    const size_t joint = requireHinge(robot, name, spec.diff_drive->plugin, tagged.first,
                                      tagged.second);
    if (std::find(side.joints.begin(), side.joints.end(), joint) != side.joints.end()) continue;
    side.joints.push_back(joint);
    side.max_radps = std::min(side.max_radps, wheelSpeedLimit(spec, tagged.second));
  }
  return side;
}

}  // namespace

Simulation::Simulation(const WorldSpec& world, const SimConfig& cfg)
    : impl_(std::make_unique<Impl>(world, cfg)) {
  if (!(cfg.physics_step_s > 0)) {
    throw std::invalid_argument("physics_step_s must be > 0, got " +
                                std::to_string(cfg.physics_step_s));
  }
  // Gazebo simulates a world's movable models as it does spawned robots.
  for (const WorldModel& model : world.models) spawnRobot(model.name, model.spec, model.pose);
}

Simulation::~Simulation() = default;

unsigned Simulation::Impl::threadCount(const SimConfig& c) {
  if (c.threads > 0) return c.threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

unsigned Simulation::threads() const { return impl_->physics->threads(); }

void Simulation::runInParallel(size_t n, const std::function<void(size_t)>& work) const {
  impl_->physics->runInParallel(n, work);
}

void Simulation::Impl::equipRobot(const std::string& name, Robot* r) {
  const RobotSpec& spec = r->spec;
  for (const RaySpec& s : spec.rays) requireLink(*r->physics, name, "ray sensor '" + s.name + "'", s.link);
  for (const ImuSpec& s : spec.imus) requireLink(*r->physics, name, "IMU '" + s.name + "'", s.link);
  for (const CameraSpec& s : spec.cameras) {
    requireLink(*r->physics, name, "camera '" + s.name + "'", s.link);
  }
  equipModelPlugins(name, r);
  equipWrenchPlugins(name, r);
  equipContactAndConeSensors(name, r);
  equipMotionPlugins(name, r);
  double joint_state_rate_hz = kDefaultJointStateRateHz;
  if (spec.diff_drive) {
    const DiffDriveSpec& d = *spec.diff_drive;
    const bool skid = !d.left_rear_joint.empty();
    std::vector<std::pair<const char*, std::string>> left = {
        {skid ? "leftFrontJoint" : "leftJoint", d.left_joint}};
    std::vector<std::pair<const char*, std::string>> right = {
        {skid ? "rightFrontJoint" : "rightJoint", d.right_joint}};
    if (skid) {
      left.emplace_back("leftRearJoint", d.left_rear_joint);
      right.emplace_back("rightRearJoint", d.right_rear_joint);
    }
    DriveSide l = driveSide(*r->physics, spec, name, left);
    DriveSide rt = driveSide(*r->physics, spec, name, right);
    r->drive.emplace(d, std::move(l.joints), std::move(rt.joints), l.max_radps, rt.max_radps);
    joint_state_rate_hz = d.update_rate_hz;
  }
  r->imus.resize(spec.imus.size());
  r->schedule = SensorSchedule(name, spec, joint_state_rate_hz);
  r->schedule.startAfter(steps, cfg.physics_step_s);
  seedSensors(name, r);
}

void Simulation::spawnRobot(const std::string& name, const RobotSpec& spec, const Pose3& pose) {
  if (impl_->robots.count(name)) throw LoadError("a robot named '" + name + "' already exists");
  if (!spec.urdf) throw LoadError("robot '" + name + "': the spec holds no parsed URDF");
  auto r = std::make_unique<Impl::Robot>();
  r->spec = spec;
  r->T_world_spawn = toIsometry(pose) * toIsometry(spec.root_link_in_model);
  RobotPlan plan = planRobot(spec);
  r->spec.warnings.insert(r->spec.warnings.end(), plan.warnings.begin(), plan.warnings.end());
  for (const std::string& warning : plan.warnings)
    impl_->pending_warnings.push_back("model '" + name + "': " + warning);
  r->id = impl_->next_robot_id;
  try {
    impl_->buildPhysics(r.get(), std::move(plan));
    impl_->equipRobot(name, r.get());
  } catch (...) {
    r->physics.reset();
    impl_->physics->dropHome(r->id);
    throw;
  }
  impl_->physics->attach(r->id, r->physics.get());
  ++impl_->next_robot_id;
  impl_->by_id.resize(impl_->next_robot_id, nullptr);
  impl_->by_id[r->id] = r.get();
  impl_->robots[name] = std::move(r);
}

bool Simulation::deleteRobot(const std::string& name) {
  impl_->forces.clearRobot(name);
  const auto it = impl_->robots.find(name);
  if (it == impl_->robots.end()) return false;
  const int id = it->second->id;
  impl_->physics->detach(id);
  impl_->by_id[id] = nullptr;
  impl_->robots.erase(it);
  impl_->physics->dropHome(id);
  return true;
}

std::vector<std::string> Simulation::robotNames() const {
  std::vector<std::pair<int, std::string>> by_spawn;
  for (const auto& r : impl_->robots) by_spawn.emplace_back(r.second->id, r.first);
  std::sort(by_spawn.begin(), by_spawn.end());
  std::vector<std::string> names;
  for (const auto& entry : by_spawn) names.push_back(entry.second);
  return names;
}

const RobotSpec& Simulation::robotSpec(const std::string& name) const {
  return impl_->robot(name).spec;
}

int Simulation::spawnGeneration(const std::string& name) const { return impl_->robot(name).id; }

void Simulation::Impl::beforeStep(Robot& r, uint64_t k) {
  const double dt = cfg.physics_step_s;
  const double timeout_s = cfg.cmd_vel_timeout_s;
  if (r.drive && r.command_active && timeout_s > 0 &&
      timeAtStep(k - 1) - r.last_command_s >= timeout_s) {
    r.drive->setCommand(0, 0);
    r.command_active = false;
  }
  if (r.drive && r.schedule.driveDue(k, dt)) {
    r.drive->updateMotors(r.physics.get(), timeAtStep(k - 1), dt);
  }
  r.physics->applyMotors(dt);
  for (size_t i = 0; i < r.plugin_wrenches.size(); ++i) {
    const Wrench& w = r.plugin_wrenches[i];
    if (w.force_n.isZero() && w.torque_nm.isZero()) continue;
    r.physics->applyLinkWrench(r.spec.forces[i].body, w);
  }
  planarMoveBeforeStep(r, k);
}

void Simulation::Impl::afterStep(Robot& r) {
  r.physics->updateJointAngles();
  r.physics->latchAppliedLoads();
  if (r.drive) r.drive->integrateEncoder(*r.physics, cfg.physics_step_s);
}

unsigned Simulation::Impl::stepsToReading(uint64_t first, unsigned max_steps) const {
  // A triggered camera's frame ends the stretch at the step it is due.
  for (const auto& entry : robots) {
    for (const std::multiset<uint64_t>& due : entry.second->camera_triggers) {
      if (due.empty()) continue;
      const uint64_t at = std::max(*due.begin(), first);
      max_steps = static_cast<unsigned>(std::min<uint64_t>(max_steps, at - first + 1));
    }
  }
  for (unsigned n = 1; n < max_steps; ++n) {
    for (const auto& entry : robots) {
      if (entry.second->schedule.anyDue(first + n - 1, cfg.physics_step_s)) return n;
    }
  }
  return max_steps;
}

std::vector<DueSensor> Simulation::step() { return stepToNextReading(1); }

std::vector<DueSensor> Simulation::stepToNextReading(unsigned max_steps, unsigned* taken) {
  Impl& impl = *impl_;
  const uint64_t first = impl.steps + 1;
  // External forces come and go with sim time: a step at a time while any is set.
  const bool forces = impl.forces.wrenchCount() > 0 || impl.forces.effortCount() > 0;
  const unsigned n = forces ? 1 : impl.stepsToReading(first, std::max(1u, max_steps));
  RobotStepHooks hooks;
  hooks.before = [&impl, first](int id, unsigned j) {
    impl.beforeStep(*impl.by_id[id], first + j);
  };
  hooks.after = [&impl](int id, unsigned) { impl.afterStep(*impl.by_id[id]); };
  impl.applyExternalForces();
  impl.physics->step(impl.cfg.physics_step_s, n, hooks);
  impl.steps = first + n - 1;
  if (taken) *taken = n;
  std::vector<DueSensor> due;
  for (auto& entry : impl.robots) {
    entry.second->schedule.collectDue(impl.steps, impl.cfg.physics_step_s, &due);
    std::vector<std::multiset<uint64_t>>& triggers = entry.second->camera_triggers;
    for (size_t i = 0; i < triggers.size(); ++i) {
      if (triggers[i].empty() || *triggers[i].begin() > impl.steps) continue;
      triggers[i].erase(triggers[i].begin());
      due.push_back({entry.first, SensorKind::Camera, i});
    }
  }
  return due;
}

void Simulation::triggerCamera(const std::string& robot, size_t index, double after_s) {
  Impl::Robot& r = impl_->robot(robot);
  if (index >= r.spec.cameras.size() || r.spec.cameras[index].trigger_topic.empty()) {
    throw std::out_of_range("robot '" + robot + "' has no triggered camera " +
                            std::to_string(index));
  }
  if (!(after_s >= 0 && std::isfinite(after_s))) {
    throw std::invalid_argument("triggerCamera: the delay of camera " + std::to_string(index) +
                                " of robot '" + robot + "' is " + std::to_string(after_s) +
                                " s, not a finite time >= 0");
  }
  // The first step that ends after_s or more on (a step's worth of rounding forgiven).
  const double steps = std::ceil(after_s / impl_->cfg.physics_step_s - 1e-9);
  r.camera_triggers.resize(r.spec.cameras.size());
  r.camera_triggers[index].insert(impl_->steps + std::max<uint64_t>(1, static_cast<uint64_t>(steps)));
}

uint64_t Simulation::seed() const { return impl_->cfg.seed; }

double Simulation::timeS() const { return impl_->timeAtStep(impl_->steps); }

void Simulation::reset() {
  // Bullet keeps contact, pair and broadphase state that moving bodies back
  // does not clear; a fresh world built in spawn order replays a run exactly.
  std::map<int, std::pair<std::string, Impl::Robot*>> by_id;
  for (auto& entry : impl_->robots) {
    impl_->physics->detach(entry.second->id);
    entry.second->physics.reset();
    by_id[entry.second->id] = {entry.first, entry.second.get()};
  }
  impl_->physics = std::make_unique<PhysicsWorlds>(impl_->world, Impl::threadCount(impl_->cfg));
  impl_->physics->setSolver(impl_->solver);
  for (auto& entry : by_id) {
    Impl::Robot& r = *entry.second.second;
    impl_->buildPhysics(&r, planRobot(r.spec));
    impl_->applyPropertyChanges(r);
    impl_->physics->attach(r.id, r.physics.get());
    if (r.drive) r.drive->reset();
    for (Wrench& w : r.plugin_wrenches) w = Wrench();
    impl_->resetMotionPlugins(&r);
    r.schedule.restart();
    // Frames asked before the reset are due from its first step on, as asked.
    for (std::multiset<uint64_t>& due : r.camera_triggers) {
      std::multiset<uint64_t> rebased;
      for (uint64_t at : due) rebased.insert(at > impl_->steps ? at - impl_->steps : 1);
      due.swap(rebased);
    }
    impl_->seedSensors(entry.second.first, &r);
  }
  impl_->steps = 0;
  impl_->epoch_s = 0;
  // Their start times were sim times of the run that is undone.
  impl_->forces.clear();
}

void Simulation::setCmdVel(const std::string& robot, double linear_mps, double angular_radps) {
  Impl::Robot& r = impl_->robot(robot);
  if (!r.drive) return;
  const double scale = r.drive->setCommand(linear_mps, angular_radps);
  if (scale < 1.0 && !r.told_wheel_limit) {
    r.told_wheel_limit = true;
    std::ostringstream text;
    text << "model '" << robot << "': cmd_vel " << linear_mps << " m/s, " << angular_radps
         << " rad/s turns a wheel faster than its joint's <limit velocity>: scaled by " << scale
         << " to fit, keeping the turn radius (said once per robot)";
    impl_->pending_warnings.push_back(text.str());
  }
  r.last_command_s = timeS();
  r.command_active = linear_mps != 0 || angular_radps != 0;
}

Pose3 Simulation::modelPose(const std::string& robot) const {
  const Impl::Robot& r = impl_->robot(robot);
  return toPose3(r.physics->linkPose(r.physics->plan().bodies[0].root_link) *
                 toIsometry(r.spec.root_link_in_model).inverse());
}

Twist3 Simulation::modelTwist(const std::string& robot) const {
  const Impl::Robot& r = impl_->robot(robot);
  const std::string& root = r.physics->plan().bodies[0].root_link;
  Twist3 twist = r.physics->linkTwist(root);
  // The model frame's origin moves as a point of the root link's body.
  const Eigen::Vector3d root_to_model =
      modelPose(robot).position - r.physics->linkPose(root).translation();
  twist.linear += twist.angular.cross(root_to_model);
  return twist;
}

ModelCondition Simulation::condition(const std::string& robot) const {
  const Impl::Robot& r = impl_->robot(robot);
  ModelCondition c;
  if (r.spec.is_static) return c;  // a static model stands as it was put, tilted or not
  const Eigen::Vector3d up =
      r.physics->linkPose(r.physics->plan().bodies[0].root_link).linear().col(2);
  c.tilt_rad = std::acos(std::clamp(up.z(), -1.0, 1.0));
  c.wall_penetration_m = r.physics->staticPenetrationM();
  return c;
}

std::vector<std::string> Simulation::takeWarnings() {
  std::vector<std::string> warnings;
  warnings.swap(impl_->pending_warnings);
  return warnings;
}

void Simulation::setModelState(const std::string& robot, const Pose3& pose, const Twist3& twist) {
  Impl::Robot& r = impl_->robot(robot);
  r.physics->moveRoot(toIsometry(pose) * toIsometry(r.spec.root_link_in_model), twist);
  for (ImuSensor& imu : r.imus) imu.reset();
}

LaserScanData Simulation::readRay(const std::string& robot, size_t index) {
  Impl::Robot& r = impl_->robot(robot);
  const RaySpec& spec = r.spec.rays.at(index);
  LaserScanData scan;
  scan.time_s = timeS();
  const Eigen::Isometry3d T_world_sensor = r.physics->linkPose(spec.link) * toIsometry(spec.pose_in_link);
  castScan(impl_->physics->rayWorld(), T_world_sensor, spec, &r.ray_rngs[index], &scan);
  return scan;
}

std::vector<LaserScanData> Simulation::readRays(const std::vector<DueSensor>& rays) {
  struct Cast {
    const RaySpec* spec;
    std::mt19937_64* rng;
    Eigen::Isometry3d T_world_sensor;
    bool cast;  ///< cast on the threads (false: it walks the broadphase, cast after)
  };
  std::vector<Cast> casts;
  casts.reserve(rays.size());
  std::set<const std::mt19937_64*> named;
  for (const DueSensor& due : rays) {
    Impl::Robot& r = impl_->robot(due.robot);
    const RaySpec& spec = r.spec.rays.at(due.index);
    std::mt19937_64* rng = &r.ray_rngs[due.index];
    if (!named.insert(rng).second) {
      throw std::invalid_argument("readRays: ray sensor " + std::to_string(due.index) +
                                  " of robot '" + due.robot + "' named twice");
    }
    casts.push_back({&spec, rng, r.physics->linkPose(spec.link) * toIsometry(spec.pose_in_link),
                     false});
  }
  std::vector<LaserScanData> scans(rays.size());
  for (LaserScanData& scan : scans) scan.time_s = timeS();
  impl_->physics->castInParallel(casts.size(), [&casts, &scans](size_t i, btCollisionWorld& scene) {
    Cast& c = casts[i];
    c.cast = castScan(scene, c.T_world_sensor, *c.spec, c.rng, &scans[i], kMaxListedScanParts,
                      /*may_walk=*/false);
  });
  for (size_t i = 0; i < casts.size(); ++i) {
    if (casts[i].cast) continue;
    const Cast& c = casts[i];
    castScan(impl_->physics->rayWorld(), c.T_world_sensor, *c.spec, c.rng, &scans[i]);
  }
  return scans;
}

std::vector<double> Simulation::castRays(const std::vector<Eigen::Vector3d>& from,
                                         const std::vector<Eigen::Vector3d>& to,
                                         const std::string& ignored_robot) {
  const int ignored_index =
      ignored_robot.empty() ? kNoIgnoredIndex : impl_->robot(ignored_robot).id;
  if (from.size() != to.size()) {
    throw std::invalid_argument("castRays: " + std::to_string(from.size()) + " start points and " +
                                std::to_string(to.size()) + " end points");
  }
  for (size_t i = 0; i < from.size(); ++i) {
    if (!from[i].allFinite() || !to[i].allFinite()) {
      throw std::invalid_argument("castRays: ray " + std::to_string(i) +
                                  " has a coordinate that is not a finite number");
    }
  }
  btCollisionWorld& scene = impl_->physics->rayWorld();
  std::vector<double> distances(from.size(), std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < from.size(); ++i) {
    const double length = (to[i] - from[i]).norm();
    if (length <= 0) continue;
    const double fraction = firstHitFraction(scene, toBt(from[i]), toBt(to[i]), ignored_index);
    if (fraction < 1.0) distances[i] = fraction * length;
  }
  return distances;
}

ImuData Simulation::readImu(const std::string& robot, size_t index) {
  Impl::Robot& r = impl_->robot(robot);
  const ImuSpec& spec = r.spec.imus.at(index);
  const Twist3 v = r.physics->linkTwist(spec.link);
  return r.imus[index].read(spec, r.physics->linkPose(spec.link), v.linear, v.angular,
                            impl_->world.gravity, timeS(), &r.imu_rngs[index]);
}

OdometryData Simulation::readOdometry(const std::string& robot) {
  Impl::Robot& r = impl_->robot(robot);
  if (!r.drive) throw std::out_of_range("robot '" + robot + "' has no diff drive");
  const DiffDriveSpec& d = *r.spec.diff_drive;
  OdometryData odom;
  odom.time_s = timeS();
  odom.frame_id = d.odometry_frame;
  odom.child_frame_id = d.robot_base_frame;
  if (d.odometry_source == OdomSource::World) {
    const std::string& root = r.physics->plan().bodies[0].root_link;
    const Eigen::Isometry3d T_world_root = r.physics->linkPose(root);
    // As Gazebo's plugin does: odometry from the world is the true world pose.
    odom.pose = toPose3(T_world_root);
    const Twist3 v = r.physics->linkTwist(root);
    odom.twist_in_child.linear = T_world_root.linear().transpose() * v.linear;
    odom.twist_in_child.angular = T_world_root.linear().transpose() * v.angular;
  } else {
    const Eigen::Vector3d& p = r.drive->encoderPose();
    odom.pose.position = Eigen::Vector3d(p.x(), p.y(), 0);
    odom.pose.orientation = Eigen::AngleAxisd(p.z(), Eigen::Vector3d::UnitZ());
    odom.twist_in_child.linear = Eigen::Vector3d(r.drive->encoderLinearMps(), 0, 0);
    odom.twist_in_child.angular = Eigen::Vector3d(0, 0, r.drive->encoderAngularRadps());
  }
  if (d.odometry_covariance_xy_yaw) {
    // x, y, yaw as given; z, roll and pitch unknown (1e12), as the skid steer plugin sets.
    const Eigen::Vector3d& c = *d.odometry_covariance_xy_yaw;
    const double diagonal[6] = {c.x(), c.y(), 1e12, 1e12, 1e12, c.z()};
    for (int i = 0; i < 6; ++i) odom.pose_covariance[i * 7] = odom.twist_covariance[i * 7] = diagonal[i];
  }
  return odom;
}

JointStateData Simulation::readJointStates(const std::string& robot) const {
  const Impl::Robot& r = impl_->robot(robot);
  JointStateData js;
  js.time_s = timeS();
  const auto& joints = r.physics->plan().joints;
  js.names.reserve(joints.size());
  js.positions.reserve(joints.size());
  js.velocities.reserve(joints.size());
  js.efforts.reserve(joints.size());
  for (size_t i = 0; i < joints.size(); ++i) {
    js.names.push_back(joints[i].name);
    js.positions.push_back(r.physics->jointPosition(i));
    js.velocities.push_back(r.physics->jointVelocity(i));
    js.efforts.push_back(0.0);
  }
  return js;
}

std::vector<LinkPose> Simulation::linkPoses(const std::string& robot) const {
  const Impl::Robot& r = impl_->robot(robot);
  std::vector<LinkPose> poses;
  poses.reserve(r.physics->plan().body_of_link.size());
  for (const auto& link : r.physics->plan().body_of_link) {
    poses.push_back({link.first, toPose3(r.physics->linkPose(link.first))});
  }
  return poses;
}

const WorldSpec& Simulation::world() const { return impl_->world; }

}  // namespace bullet_sim
