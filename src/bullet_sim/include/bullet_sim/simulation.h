#ifndef BULLET_SIM_SIMULATION_H
#define BULLET_SIM_SIMULATION_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/sensors/sensor_data.h"
#include "bullet_sim/types.h"
#include "bullet_sim/world/entity_frames.h"
#include "bullet_sim/world/external_forces.h"

namespace bullet_sim {

/// Physics settings of a Simulation.
struct SimConfig {
  double physics_step_s = 0.001;
  uint64_t seed = 1;  ///< every sensor's noise is seeded from (seed, robot, sensor)
  /// A robot whose last setCmdVel is older than this (sim seconds) is given a zero command;
  /// 0 = never (Gazebo's diff drive keeps the last command forever).
  double cmd_vel_timeout_s = 0;
  /// Threads that step the robots' physics (robots that cannot touch each other within a
  /// step are simulated apart, in parallel); 0 = the machine's hardware threads, 1 = the
  /// calling thread only. Results are the same to the bit whatever the number.
  unsigned threads = 0;
};

/// A link's mass properties and gravity as set_link_properties changes them (the URDF's
/// <inertial> until then).
struct LinkProperties {
  double mass_kg = 0;
  Pose3 com_in_link;  ///< centre of mass and inertial axes in the link frame
  double ixx = 0, ixy = 0, ixz = 0, iyy = 0, iyz = 0, izz = 0;  ///< about the COM, inertial axes
  bool gravity = true;  ///< whether gravity acts on the link
};

/// What set_joint_properties may change on a hinge. Unset fields keep their value.
struct JointDynamics {
  std::optional<double> damping_nms_per_rad;  ///< viscous: torque -damping * rate, each step
  std::optional<double> lower_rad, upper_rad; ///< limits (both -> lower > upper: no limit)
  std::optional<double> erp, cfm, stop_erp, stop_cfm;  ///< Bullet's hinge parameters
  std::optional<double> motor_velocity_radps, motor_max_torque_nm;  ///< a motor (both or none)
};

/// How a model stands: upright or tipped over, free or pushed into a static body.
struct ModelCondition {
  double tilt_rad = 0;           ///< angle between the root link's z axis and the world's
  double wall_penetration_m = 0; ///< deepest reach of any of its bodies into a static body
  bool tippedOver() const { return tilt_rad > 0.7853981633974483; }  ///< beyond 45 degrees
  bool inWall() const { return wall_penetration_m > 0.01; }        ///< deeper than 1 cm
};

/// The simulated world with its robots. Sim time only: nothing reads a clock.
/// Every robot-taking method throws std::out_of_range for an unknown robot.
class Simulation {
 public:
  /// Spawns the world's movable models (WorldSpec::models) as robots of their names.
  /// @throws LoadError as spawnRobot does.
  Simulation(const WorldSpec& world, const SimConfig& cfg);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// `pose`: the model frame in the world (the root link goes to pose * spec.root_link_in_model).
  /// @throws LoadError on a name clash, a diff drive naming a missing joint, ...
  void spawnRobot(const std::string& name, const RobotSpec& spec, const Pose3& pose);
  bool deleteRobot(const std::string& name);
  /// Every model simulated as a robot (the world's movable models first), in spawn order.
  std::vector<std::string> robotNames() const;
  const RobotSpec& robotSpec(const std::string& name) const;
  /// The number this spawn of `name` was given: every spawn gets the next one (the world's
  /// movable models count from 0), and none is reused, so a robot deleted and spawned again
  /// under the same name has a new one. Caches of a robot's build (the camera's drawn
  /// visuals) key on it, where the address of its spec could be reused.
  int spawnGeneration(const std::string& name) const;

  /// Advances exactly one physics step and returns the sensors whose update
  /// period elapsed at this step. Nothing is computed for them here.
  std::vector<DueSensor> step();
  /// Advances up to `max_steps` physics steps (at least one), stopping after the first at
  /// which a sensor is due, and returns the sensors due then (none when it took
  /// `max_steps` without one). The same as step() called as often, except that robots are
  /// grouped into worlds once for all of them (robots that may touch within them share a
  /// world), so that each world takes them on one thread without waiting for the others.
  /// While an external wrench or effort is set it takes one step. With `taken`, says how
  /// many steps it took.
  std::vector<DueSensor> stepToNextReading(unsigned max_steps, unsigned* taken = nullptr);
  /// Asks triggered camera `index` of `robot` (CameraSpec::trigger_topic) for one frame,
  /// due at the first step that ends `after_s` of sim time or more from now (the next step
  /// at the earliest): one frame per call, a camera's frames due at the same step served
  /// one per step, as Gazebo's triggered camera renders once per trigger, one frame a
  /// render. `after_s` stands for the sim time that passes in Gazebo while its render
  /// thread draws the frame, its world stepping on.
  /// @throws std::out_of_range for an unknown robot or a camera that is not triggered.
  void triggerCamera(const std::string& robot, size_t index, double after_s = 0);
  /// SimConfig::seed: sensor noise (cameras' too) is seeded from it, the robot and sensor.
  uint64_t seed() const;
  double timeS() const;
  /// The threads that step the physics (SimConfig::threads, 0 resolved).
  unsigned threads() const;
  /// Calls work(i) once for each i in [0, n) on the threads that step the physics and
  /// returns when all have returned; then rethrows the first exception a piece threw (the
  /// other pieces run all the same). For work beside the simulation that shares it out
  /// (CameraRenderer::renderTogether draws one camera frame per piece): the pieces must be
  /// independent of each other and may read the simulation, not change it. Whether the
  /// helper threads are used is measured for this work apart from the steps and the scans
  /// (its pieces cost otherwise), as the steps' is. Call it where step() is called, never
  /// from inside a piece; the simulation itself is left as it was.
  void runInParallel(size_t n, const std::function<void(size_t)>& work) const;
  /// Sim time to 0, robots back to their spawn poses at rest, commands zero, external
  /// wrenches and efforts cleared.
  void reset();

  /// The diff drive's command. One that would turn a wheel faster than its joint's URDF
  /// <limit velocity> is scaled down to fit, keeping the turn radius; the first time for a
  /// robot, takeWarnings() says so.
  void setCmdVel(const std::string& robot, double linear_mps, double angular_radps);
  Pose3 modelPose(const std::string& robot) const;  ///< model frame in the world
  Twist3 modelTwist(const std::string& robot) const;
  ModelCondition condition(const std::string& robot) const;
  /// What the simulation noticed since the last call (how each robot was built: joints held
  /// fixed, mesh collisions, masses given), each message once, naming the model.
  std::vector<std::string> takeWarnings();
  void setModelState(const std::string& robot, const Pose3& pose, const Twist3& twist);

  // Sensor reads, computed on demand: a sensor nobody reads costs nothing.
  LaserScanData readRay(const std::string& robot, size_t index);
  /// The scans of several ray sensors at once (`rays`: a robot and the index of one of its
  /// rays each, as DueSensor names them; each sensor once), cast on the physics threads:
  /// each the same as readRay() would read it, in the order given.
  /// @throws std::invalid_argument for a sensor named twice.
  std::vector<LaserScanData> readRays(const std::vector<DueSensor>& rays);
  /// Casts the segments from[i] -> to[i] through the world's static shapes and every
  /// robot's collisions as they are now (what the ray sensors see), returning for each the
  /// distance from from[i] to the first hit, +inf where the segment hits nothing. For
  /// queries beside the sensors: free space, line of sight. The collisions of
  /// `ignored_robot` (a robot's name; "" for none) are not hit.
  /// @throws std::invalid_argument for lists of different lengths or a non-finite point;
  /// std::out_of_range for an unknown ignored robot.
  std::vector<double> castRays(const std::vector<Eigen::Vector3d>& from,
                               const std::vector<Eigen::Vector3d>& to,
                               const std::string& ignored_robot = "");
  ImuData readImu(const std::string& robot, size_t index);
  /// A libgazebo_ros_range.so sensor's reading, its rays cast now.
  RangeData readRange(const std::string& robot, size_t index);
  /// A libgazebo_ros_block_laser.so sensor's points, its rays cast now.
  BlockLaserCloudData readBlockLaser(const std::string& robot, size_t index);
  /// What touches a libgazebo_ros_bumper.so sensor's collision, from the last step's
  /// contacts: a state per other collision, the sensor's as collision 1.
  ContactsData readBumper(const std::string& robot, size_t index) const;
  OdometryData readOdometry(const std::string& robot);
  JointStateData readJointStates(const std::string& robot) const;  ///< every non-fixed joint
  /// libgazebo_ros_p3d.so plugin `index` (RobotSpec::p3ds): the ground truth of its body,
  /// its noise drawn from its own seeded generator. Its twist is in the world's axes (or
  /// the frame link's, as Gazebo turns it), not the child's.
  OdometryData readGroundTruth(const std::string& robot, size_t index);
  /// libgazebo_ros_force.so plugin `index` (RobotSpec::forces): the wrench (world axes, at
  /// the body's centre of mass) that acts at every step from now on, as its topic's last
  /// message does in Gazebo. A world reset sets it back to zero.
  void setPluginWrench(const std::string& robot, size_t index, const Wrench& wrench);
  /// libgazebo_ros_planar_move.so's command (RobotSpec::planar_move): x and y (m/s) in the
  /// model's yaw frame and the yaw rate (rad/s), given to every link of the model at every
  /// step from the next on (its z velocity and roll and pitch rates set to 0), until a new
  /// one or the plugin's <cmdTimeout>. A world reset sets it back to zero.
  /// @throws std::out_of_range for a robot without the plugin.
  void setPlanarMoveCommand(const std::string& robot, double x_mps, double y_mps,
                            double yaw_radps);
  /// libgazebo_ros_planar_move.so's odometry: the model's world pose, its twist measured
  /// from the previous reading (the first from the spawn), which this one becomes.
  /// @throws std::out_of_range for a robot without the plugin.
  OdometryData readPlanarMoveOdometry(const std::string& robot);
  /// libgazebo_ros_joint_state_publisher.so plugin `index` (RobotSpec::joint_state_publishers):
  /// its joints' positions and velocities, in the order it names them; efforts left empty.
  JointStateData readPluginJointStates(const std::string& robot, size_t index) const;
  /// libgazebo_ros_f3d.so plugin `index` (RobotSpec::f3ds): the wrench applied to its body
  /// in the last step from outside (force plugins, apply_body_wrench, joint efforts; not
  /// gravity, contacts or joint constraints), world axes, torque about the body's centre of
  /// mass, whatever its frameName (the frame_id only), as Gazebo's plugin reads it.
  WrenchData readF3d(const std::string& robot, size_t index) const;
  /// libgazebo_ros_ft_sensor.so plugin `index` (RobotSpec::ft_sensors): the wrench its
  /// joint passed in the last step, as the child link exerts it on the joint (minus what
  /// the joint exerts on the child), in the child link's frame, torque about the joint
  /// origin; each of the six values plus Gaussian noise of sd gaussianNoise from its own
  /// seeded generator. frame_id: the child link.
  WrenchData readForceTorque(const std::string& robot, size_t index);
  std::vector<LinkPose> linkPoses(const std::string& robot) const;
  const WorldSpec& world() const;

  // Models, links and joints by Gazebo's names ("model", "model::link"). Link and joint
  // taking methods throw std::out_of_range naming an unknown link or joint.

  /// "model" or "model::link" of an existing robot and link; std::nullopt otherwise
  /// (also for "" and "world", which are the world frame, not entities).
  std::optional<EntityName> findEntity(const std::string& name) const;
  /// World state of an entity found by findEntity (a model: its root link).
  EntityState entityState(const EntityName& entity) const;
  /// World state of a reference frame named as the services take it: "" and "world"
  /// are the world frame (identity, at rest), else an entity, else "map" and "/map" are
  /// the world as in gazebo_ros; std::nullopt if unknown.
  std::optional<EntityState> frameState(const std::string& name) const;
  /// Every URDF link of a robot, sorted by name; the root link is the model's frame.
  std::vector<std::string> linkNames(const std::string& robot) const;
  std::string rootLink(const std::string& robot) const;
  EntityState linkState(const std::string& robot, const std::string& link) const;
  /// Moves the robot rigidly, keeping its joint angles, so that `link` lands on `pose`
  /// with `twist` (the velocity of the link's origin; the rest of the robot turns with it).
  void setLinkState(const std::string& robot, const std::string& link, const Pose3& pose,
                    const Twist3& twist);

  /// A movable joint named "model::joint", or by its bare name (the first model in name
  /// order that has it, as Gazebo searches); `link` of the result holds the joint name.
  std::optional<EntityName> findJoint(const std::string& name) const;
  /// The robot's movable joints (revolute and continuous), sorted by name.
  std::vector<std::string> jointNames(const std::string& robot) const;
  double jointPosition(const std::string& robot, const std::string& joint) const;
  double jointVelocity(const std::string& robot, const std::string& joint) const;
  /// Puts the named joints at the given angles (rad), the others where they are, the root
  /// link where it is, every body of the robot at rest.
  void setJointPositions(const std::string& robot, const std::map<std::string, double>& positions);

  /// apply_body_wrench / apply_joint_effort bookkeeping, applied at every step.
  ExternalForces& externalForces();

  // Physics settings, changeable while running.
  double physicsStepS() const;
  /// The next steps are `step_s` long; sim time runs on from where it is.
  /// @throws std::invalid_argument unless 0 < step_s.
  void setPhysicsStep(double step_s);
  Eigen::Vector3d gravity() const;
  void setGravity(const Eigen::Vector3d& gravity_mps2);
  SolverSettings solverSettings() const;
  /// From the next step on, in every world (kept across reset()).
  /// @throws std::invalid_argument naming the field out of range.
  void setSolverSettings(const SolverSettings& settings);

  // Lights of the world (world().lights), by name: what the camera lights the scene with.
  /// Replaces the light of `light.name`; false (nothing changed) when there is none.
  bool setLight(const LightSpec& light);
  /// Removes the light; false when there is none of that name.
  bool deleteLight(const std::string& name);

  // Link and joint properties (set_link_properties, set_joint_properties). Changes are
  // kept across reset(), as Gazebo keeps them. Both throw std::out_of_range for an unknown
  // robot, link or joint, and std::invalid_argument naming the field that cannot be
  // honoured (nothing is changed then).
  LinkProperties linkProperties(const std::string& robot, const std::string& link) const;
  /// Mass and inertia of a link that is a body of its own (not merged with others by fixed
  /// joints), about an unchanged centre of mass and diagonal in the body's principal axes;
  /// gravity per body.
  void setLinkProperties(const std::string& robot, const std::string& link,
                         const LinkProperties& properties);
  /// The damping, limits, Bullet parameters and motor of a joint as last set (limits from
  /// the URDF until then).
  JointDynamics jointDynamics(const std::string& robot, const std::string& joint) const;
  void setJointDynamics(const std::string& robot, const std::string& joint,
                        const JointDynamics& dynamics);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_SIMULATION_H
