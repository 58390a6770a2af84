#include "services/physics_services.h"

#include "topics/conversions.h"

#include <cmath>
#include <optional>
#include <string>

namespace bullet_sim_node {
namespace {

/// Bullet's solver settings (btContactSolverInfo defaults, which the simulation keeps) in
/// the fields of ODE's: 10 iterations, SOR 1, ERP 0.2, no CFM, 4 contact points per
/// pair, resting bodies sleep.
gazebo_msgs::ODEPhysics solverSettings() {
  gazebo_msgs::ODEPhysics ode;
  ode.auto_disable_bodies = true;
  ode.sor_pgs_iters = 10;
  ode.sor_pgs_w = 1.0;
  ode.erp = 0.2;
  ode.max_contacts = 4;
  return ode;
}

/// ode_config is accepted when it is what get_physics_properties reports or left unset
/// (all zero): Bullet's solver cannot take ODE's settings.
bool isAcceptedSolverConfig(const gazebo_msgs::ODEPhysics& ode) {
  return ode == solverSettings() || ode == gazebo_msgs::ODEPhysics();
}

/// Why a set_physics_properties request cannot be honoured, if it cannot.
std::optional<std::string> invalidPhysics(const gazebo_msgs::SetPhysicsProperties::Request& req) {
  if (!(std::isfinite(req.time_step) && req.time_step > 0 && req.time_step <= 0.1))
    return "time_step " + std::to_string(req.time_step) + " is not in (0, 0.1] s";
  if (!(std::isfinite(req.max_update_rate) && req.max_update_rate >= 0))
    return "max_update_rate " + std::to_string(req.max_update_rate) +
           " is not >= 0 (0: as fast as possible)";
  if (auto bad = firstNonFinite(req.gravity, "gravity")) return *bad + " is not finite";
  if (!isAcceptedSolverConfig(req.ode_config))
    return std::string("ode_config differs from what get_physics_properties reports: ") +
           "Bullet's solver settings cannot be changed (leave ode_config as reported or unset)";
  return std::nullopt;
}

}  // namespace

PhysicsServices::PhysicsServices(SimRunner& runner, Pacer& pacer, const ros::NodeHandle& gazebo_nh)
    : runner_(runner), pacer_(pacer) {
  ros::NodeHandle nh(gazebo_nh);
  servers_ = {
      nh.advertiseService("pause_physics", &PhysicsServices::pause, this),
      nh.advertiseService("unpause_physics", &PhysicsServices::unpause, this),
      nh.advertiseService("reset_simulation", &PhysicsServices::resetSimulation, this),
      nh.advertiseService("reset_world", &PhysicsServices::resetWorld, this),
      nh.advertiseService("step_simulation", &PhysicsServices::step, this),
      nh.advertiseService("get_physics_properties", &PhysicsServices::getPhysics, this),
      nh.advertiseService("set_physics_properties", &PhysicsServices::setPhysics, this),
  };
}

bool PhysicsServices::pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  runner_.setPaused(true);
  return true;
}

bool PhysicsServices::unpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  runner_.setPaused(false);
  return true;
}

bool PhysicsServices::resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  runner_.sim().reset();
  runner_.publishClock();
  return true;
}

bool PhysicsServices::resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  for (const std::string& robot : runner_.sim().robotNames()) {
    runner_.sim().setCmdVel(robot, 0, 0);
    runner_.sim().setModelState(robot, runner_.spawnPose(robot), bullet_sim::Twist3{});
  }
  return true;
}

bool PhysicsServices::step(bullet_sim::StepSimulation::Request& req,
                           bullet_sim::StepSimulation::Response& res) {
  if (!runner_.paused()) {
    res.status_message = "physics is running: call pause_physics before stepping";
  } else {
    for (uint32_t done = 0; done < req.steps;) done += runner_.step(req.steps - done);
    runner_.publishClock();
    runner_.flushMessages();  // the caller may count them once the call returns
    res.success = true;
    res.status_message = "stepped " + std::to_string(req.steps) + " steps";
  }
  res.sim_time.fromSec(runner_.sim().timeS());
  return true;
}

bool PhysicsServices::getPhysics(gazebo_msgs::GetPhysicsProperties::Request&,
                                 gazebo_msgs::GetPhysicsProperties::Response& res) {
  const bullet_sim::Simulation& sim = runner_.sim();
  res.time_step = sim.physicsStepS();
  res.pause = runner_.paused();
  res.max_update_rate = pacer_.realTimeFactor() / sim.physicsStepS();
  const Eigen::Vector3d g = sim.gravity();
  res.gravity.x = g.x();
  res.gravity.y = g.y();
  res.gravity.z = g.z();
  res.ode_config = solverSettings();
  res.success = true;
  res.status_message = "GetPhysicsProperties: got properties";
  return true;
}

bool PhysicsServices::setPhysics(gazebo_msgs::SetPhysicsProperties::Request& req,
                                 gazebo_msgs::SetPhysicsProperties::Response& res) {
  if (const std::optional<std::string> invalid = invalidPhysics(req)) {
    res.success = false;
    res.status_message = "SetPhysicsProperties: " + *invalid;
    return true;
  }
  bullet_sim::Simulation& sim = runner_.sim();
  sim.setPhysicsStep(req.time_step);
  sim.setGravity(Eigen::Vector3d(req.gravity.x, req.gravity.y, req.gravity.z));
  pacer_.setRealTimeFactor(req.max_update_rate * req.time_step, sim.timeS());
  res.success = true;
  res.status_message = "SetPhysicsProperties: time step " + std::to_string(req.time_step) +
                       " s, real-time factor " +
                       std::to_string(req.max_update_rate * req.time_step);
  return true;
}

}  // namespace bullet_sim_node
