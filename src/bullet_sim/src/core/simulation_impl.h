#ifndef BULLET_SIM_CORE_SIMULATION_IMPL_H
#define BULLET_SIM_CORE_SIMULATION_IMPL_H

// The state behind Simulation, shared by the files that implement it
// (simulation.cpp: robots, stepping, sensors; simulation_entities.cpp: links, joints,
// external forces and physics settings).

#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bullet_sim/simulation.h"
#include "bullet_sim/world/external_forces.h"
#include "physics/diff_drive.h"
#include "physics/physics_robot.h"
#include "physics/physics_worlds.h"
#include "physics/planar_move.h"
#include "sensors/imu_sensor.h"
#include "sensors/planar_odometry.h"
#include "sensors/sensor_schedule.h"

namespace bullet_sim {

struct Simulation::Impl {
  struct Robot {
    /// Spawn generation (Simulation::spawnGeneration), also Bullet's user index of its
    /// bodies; rebuilding in this order replays a run exactly.
    int id;
    RobotSpec spec;
    Eigen::Isometry3d T_world_spawn;
    std::unique_ptr<PhysicsRobot> physics;
    std::optional<DiffDriveController> drive;
    double last_command_s = 0;   ///< sim time of the last setCmdVel
    bool command_active = false; ///< a non-zero command the timeout may stop
    bool told_wheel_limit = false;  ///< a command was scaled to the wheel limits and we said so
    std::vector<std::mt19937_64> ray_rngs, imu_rngs, p3d_rngs, range_rngs,
        block_laser_rngs;
    /// The last wrench of each libgazebo_ros_force.so plugin (RobotSpec::forces), applied
    /// at every step.
    std::vector<Wrench> plugin_wrenches;
    /// libgazebo_ros_planar_move.so (RobotSpec::planar_move) and its odometry.
    std::optional<PlanarMoveDrive> planar_move;
    PlanarOdometry planar_odometry;
    /// Each libgazebo_ros_joint_state_publisher.so's joints, as indices into the plan's.
    std::vector<std::vector<size_t>> joint_state_plugin_joints;
    /// Each bumper's collision: its body and the index of the collision in that body's plan.
    struct BumperTarget {
      size_t body = 0, part = 0;
      std::string name;  ///< "model::link::collision", as Gazebo scopes it
    };
    std::vector<BumperTarget> bumpers;
    /// Each libgazebo_ros_ft_sensor.so plugin's hinge (index into the plan's joints) and
    /// noise generator.
    std::vector<size_t> ft_joints;
    std::vector<std::mt19937_64> ft_rngs;
    std::vector<ImuSensor> imus;
    SensorSchedule schedule;
    /// set_link_properties / set_joint_properties changes, put back after a reset().
    std::map<std::string, LinkProperties> link_changes;
    std::map<std::string, JointDynamics> joint_changes;
    /// The steps at which each triggered camera's asked frames are due (one per frame).
    std::vector<std::multiset<uint64_t>> camera_triggers;
  };

  Impl(const WorldSpec& w, const SimConfig& c)
      : world(w), cfg(c), physics(std::make_unique<PhysicsWorlds>(w, threadCount(c))) {}

  /// SimConfig::threads, 0 standing for the machine's hardware threads.
  static unsigned threadCount(const SimConfig& c);

  /// Checks that the sensors and the drive of robot r (built) name its links and joints,
  /// and sets up its drive, sensors and their schedule.
  /// @throws LoadError naming what is missing.
  void equipRobot(const std::string& name, Robot* r);
  /// The part of equipRobot for the model plugins of gazebo_plugins (p3d, force): checks
  /// the links they name and sets up their state. @throws LoadError naming what is missing.
  void equipModelPlugins(const std::string& name, Robot* r);
  /// The part of equipRobot for the planar move and joint state publisher plugins: checks
  /// the joints they name. @throws LoadError naming the plugin and the joint.
  void equipMotionPlugins(const std::string& name, Robot* r);
  /// After a world reset: no planar move command, its odometry from the spawn pose.
  void resetMotionPlugins(Robot* r) const;
  /// The planar move plugin's work at the start of step k: the model's velocity.
  void planarMoveBeforeStep(Robot& r, uint64_t k) const;
  /// The model frame of robot r in the world.
  static Eigen::Isometry3d modelFrame(const Robot& r);
  /// The part of equipRobot for the plugins that publish wrenches (f3d, ft_sensor): checks
  /// the links and joints they name. @throws LoadError naming what is missing.
  void equipWrenchPlugins(const std::string& name, Robot* r);
  /// The part of equipRobot for range sensors, block lasers and bumpers.
  void equipContactAndConeSensors(const std::string& name, Robot* r);
  /// Gazebo's scoped name ("model::link::collision") of part `part` of `object` (a robot's
  /// body or a static shape), "" for anything else.
  std::string collisionName(const btCollisionObject* object, int part) const;

  /// Builds robot r's bodies in a home world of its own; physics->attach() them once the
  /// robot is complete.
  void buildPhysics(Robot* r, RobotPlan plan) {
    btDiscreteDynamicsWorld* home = physics->addHome(r->id);
    r->physics = std::make_unique<PhysicsRobot>(home, r->id, std::move(plan), r->T_world_spawn);
  }

  Robot& robot(const std::string& name) {
    auto it = robots.find(name);
    if (it == robots.end()) throw std::out_of_range("no robot named '" + name + "'");
    return *it->second;
  }
  const Robot& robot(const std::string& name) const {
    return const_cast<Impl*>(this)->robot(name);
  }

  void seedSensors(const std::string& name, Robot* r) const {
    r->ray_rngs.clear();
    r->imu_rngs.clear();
    r->p3d_rngs.clear();
    for (const RaySpec& s : r->spec.rays) r->ray_rngs.push_back(sensorRng(cfg.seed, name, s.name));
    for (const P3dSpec& s : r->spec.p3ds) {
      r->p3d_rngs.push_back(sensorRng(cfg.seed, name, "p3d " + s.name + " " + s.topic));
    }
    for (const ImuSpec& s : r->spec.imus) r->imu_rngs.push_back(sensorRng(cfg.seed, name, s.name));
    r->range_rngs.clear();
    r->block_laser_rngs.clear();
    for (const RangeSpec& s : r->spec.ranges)
      r->range_rngs.push_back(sensorRng(cfg.seed, name, s.name));
    for (const BlockLaserSpec& s : r->spec.block_lasers)
      r->block_laser_rngs.push_back(sensorRng(cfg.seed, name, s.name));
    r->ft_rngs.clear();
    for (const FtSensorSpec& s : r->spec.ft_sensors) {
      r->ft_rngs.push_back(sensorRng(cfg.seed, name, "ft_sensor " + s.name + " " + s.topic));
    }
    for (ImuSensor& imu : r->imus) imu.reset();
  }

  /// Sim time at the end of step k (counted from the last change of the physics step).
  double timeAtStep(uint64_t k) const { return epoch_s + static_cast<double>(k) * cfg.physics_step_s; }

  /// Applies robot r's link and joint property changes to its (rebuilt) physics.
  void applyPropertyChanges(Robot& r) const;

  /// Adds the external wrenches and joint efforts acting in the coming step.
  void applyExternalForces();
  /// Robot r's own work before step k: its command's timeout, its drive's update, its
  /// motors. Touches r only (it runs on the thread that steps r's world).
  void beforeStep(Robot& r, uint64_t k);
  /// Robot r's own work once step k is taken: joint angles, wheel encoders. Touches r only.
  void afterStep(Robot& r);
  /// How many steps from step `first` on, at most `max_steps`, end with the first step at
  /// which a sensor of some robot is due (max_steps when none is due in them).
  unsigned stepsToReading(uint64_t first, unsigned max_steps) const;

  WorldSpec world;  ///< as loaded, with the gravity currently set
  SimConfig cfg;
  std::unique_ptr<PhysicsWorlds> physics;
  std::map<std::string, std::unique_ptr<Robot>> robots;
  std::vector<Robot*> by_id;  ///< robots by id (null for ids no robot holds now)
  /// Steps since `epoch_s`, the sim time of the last physics-step change: sensor
  /// schedules count in steps of the current length from there.
  uint64_t steps = 0;
  double epoch_s = 0;
  int next_robot_id = 0;
  std::vector<std::string> pending_warnings;  ///< for Simulation::takeWarnings()
  ExternalForces forces;
  SolverSettings solver;  ///< as last set, given to every new PhysicsWorlds
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SIMULATION_IMPL_H
