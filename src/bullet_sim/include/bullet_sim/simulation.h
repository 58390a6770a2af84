#ifndef BULLET_SIM_SIMULATION_H
#define BULLET_SIM_SIMULATION_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim/robot_spec.h"
#include "bullet_sim/sensor_data.h"
#include "bullet_sim/types.h"
#include "bullet_sim/world_spec.h"

namespace bullet_sim {

/// Physics settings of a Simulation.
struct SimConfig {
  double physics_step_s = 0.001;
  uint64_t seed = 1;  ///< every sensor's noise is seeded from (seed, robot, sensor)
};

enum class SensorKind { Ray, Imu, Camera, Odometry, JointStates };

/// A sensor whose update period elapsed; index points into the robot spec's
/// vector of that kind (0 for Odometry and JointStates).
struct DueSensor {
  std::string robot;
  SensorKind kind;
  size_t index;
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
  std::vector<std::string> robotNames() const;
  const RobotSpec& robotSpec(const std::string& name) const;

  /// Advances exactly one physics step and returns the sensors whose update
  /// period elapsed at this step. Nothing is computed for them here.
  std::vector<DueSensor> step();
  double timeS() const;
  /// Sim time to 0, robots back to their spawn poses at rest, commands zero.
  void reset();

  void setCmdVel(const std::string& robot, double linear_mps, double angular_radps);
  Pose3 modelPose(const std::string& robot) const;  ///< model frame in the world
  Twist3 modelTwist(const std::string& robot) const;
  void setModelState(const std::string& robot, const Pose3& pose, const Twist3& twist);

  // Sensor reads, computed on demand: a sensor nobody reads costs nothing.
  LaserScanData readRay(const std::string& robot, size_t index);
  ImuData readImu(const std::string& robot, size_t index);
  OdometryData readOdometry(const std::string& robot);
  JointStateData readJointStates(const std::string& robot) const;  ///< every non-fixed joint
  std::vector<LinkPose> linkPoses(const std::string& robot) const;
  const WorldSpec& world() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_SIMULATION_H
