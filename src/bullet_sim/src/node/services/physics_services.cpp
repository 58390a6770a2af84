#include "services/physics_services.h"

#include "topics/conversions.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace bullet_sim_node {
namespace {

/// ODE's fields that Bullet has no counterpart for, as reported: resting bodies sleep,
/// Bullet's contact manifold keeps 4 points, the rest has no equivalent (0).
gazebo_msgs::ODEPhysics fixedOdeFields() {
  gazebo_msgs::ODEPhysics ode;
  ode.auto_disable_bodies = true;
  ode.max_contacts = 4;
  return ode;
}

/// The first of ODE's fields without a Bullet counterpart that `ode` changes, if any.
std::optional<std::string> changedFixedField(const gazebo_msgs::ODEPhysics& ode) {
  const gazebo_msgs::ODEPhysics fixed = fixedOdeFields();
  if (ode.auto_disable_bodies != fixed.auto_disable_bodies) return "auto_disable_bodies";
  if (ode.sor_pgs_precon_iters != fixed.sor_pgs_precon_iters) return "sor_pgs_precon_iters";
  if (ode.sor_pgs_rms_error_tol != fixed.sor_pgs_rms_error_tol) return "sor_pgs_rms_error_tol";
  if (ode.contact_surface_layer != fixed.contact_surface_layer) return "contact_surface_layer";
  if (ode.contact_max_correcting_vel != fixed.contact_max_correcting_vel)
    return "contact_max_correcting_vel";
  if (ode.max_contacts != fixed.max_contacts) return "max_contacts";
  return std::nullopt;
}

/// Why a set_physics_properties request cannot be honoured, if it cannot.
std::optional<std::string> invalidPhysics(const gazebo_msgs::SetPhysicsProperties::Request& req) {
  if (!(std::isfinite(req.time_step) && req.time_step > 0 && req.time_step <= 0.1))
    return "time_step " + std::to_string(req.time_step) + " is not in (0, 0.1] s";
  if (!(std::isfinite(req.max_update_rate) && req.max_update_rate >= 0))
    return "max_update_rate " + std::to_string(req.max_update_rate) +
           " is not >= 0 (0: as fast as possible)";
  if (auto bad = firstNonFinite(req.gravity, "gravity")) return *bad + " is not finite";
  if (req.ode_config == gazebo_msgs::ODEPhysics()) return std::nullopt;  // unset: kept
  if (auto field = changedFixedField(req.ode_config)) {
    return "ode_config." + *field + " has no equivalent in Bullet: leave it as " +
           "get_physics_properties reports it";
  }
  return std::nullopt;
}

}  // namespace

PhysicsServices::PhysicsServices(SimRunner& runner, Pacer& pacer, const ros::NodeHandle& gazebo_nh,
                                 bool step_service)
    : runner_(runner), pacer_(pacer) {
  ros::NodeHandle nh(gazebo_nh);
  servers_ = {
      nh.advertiseService("pause_physics", &PhysicsServices::pause, this),
      nh.advertiseService("unpause_physics", &PhysicsServices::unpause, this),
      nh.advertiseService("reset_simulation", &PhysicsServices::resetSimulation, this),
      nh.advertiseService("reset_world", &PhysicsServices::resetWorld, this),
      nh.advertiseService("get_physics_properties", &PhysicsServices::getPhysics, this),
      nh.advertiseService("set_physics_properties", &PhysicsServices::setPhysics, this),
  };
  if (step_service) {
    servers_.push_back(nh.advertiseService("step_simulation", &PhysicsServices::step, this));
    servers_.push_back(nh.advertiseService("step_control", &PhysicsServices::stepControl, this));
  }
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
    advance(req.steps);
    res.success = true;
    res.status_message = "stepped " + std::to_string(req.steps) + " steps";
  }
  res.sim_time.fromSec(runner_.sim().timeS());
  return true;
}

bool PhysicsServices::stepControl(gazebo_msgs::StepControl::Request& req,
                                  gazebo_msgs::StepControl::Response& res) {
  // As the request proposes: 0 resumes the physics, n >= 1 pauses it (if it runs) and
  // takes n steps; the reply comes once they are done, not when they are asked for.
  if (req.steps == 0) {
    runner_.setPaused(false);
    res.status_message = "StepControl: 0 steps: physics unpaused";
  } else {
    runner_.setPaused(true);
    advance(req.steps);
    res.status_message = "StepControl: " + std::to_string(req.steps) +
                         " steps taken, paused at sim time " + std::to_string(runner_.sim().timeS());
  }
  res.success = true;
  return true;
}

void PhysicsServices::advance(uint32_t steps) {
  for (uint32_t done = 0; done < steps;) done += runner_.step(steps - done);
  runner_.publishClock();
  runner_.flushMessages();  // the caller may count them once the call returns
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
  res.ode_config = odeConfig(sim.solverSettings());
  res.success = true;
  res.status_message = "GetPhysicsProperties: got properties";
  return true;
}

bool PhysicsServices::setPhysics(gazebo_msgs::SetPhysicsProperties::Request& req,
                                 gazebo_msgs::SetPhysicsProperties::Response& res) {
  const std::string error = applyPhysics(req);
  res.success = error.empty();
  if (!res.success) {
    res.status_message = "SetPhysicsProperties: " + error;
    return true;
  }
  res.status_message = "SetPhysicsProperties: time step " + std::to_string(req.time_step) +
                       " s, real-time factor " +
                       std::to_string(req.max_update_rate * req.time_step);
  if (on_change_) on_change_();
  return true;
}

std::string PhysicsServices::applyPhysics(const gazebo_msgs::SetPhysicsProperties::Request& req) {
  if (const std::optional<std::string> invalid = invalidPhysics(req)) return *invalid;
  bullet_sim::Simulation& sim = runner_.sim();
  if (req.ode_config != gazebo_msgs::ODEPhysics()) {
    bullet_sim::SolverSettings solver;
    solver.iterations = static_cast<int>(req.ode_config.sor_pgs_iters);
    solver.sor = req.ode_config.sor_pgs_w;
    solver.erp = req.ode_config.erp;
    solver.cfm = req.ode_config.cfm;
    try {
      sim.setSolverSettings(solver);
    } catch (const std::invalid_argument& error) {
      return std::string("ode_config: ") + error.what();
    }
  }
  sim.setPhysicsStep(req.time_step);
  sim.setGravity(Eigen::Vector3d(req.gravity.x, req.gravity.y, req.gravity.z));
  pacer_.setRealTimeFactor(req.max_update_rate * req.time_step, sim.timeS());
  return "";
}

gazebo_msgs::GetPhysicsProperties::Response PhysicsServices::currentPhysics() {
  gazebo_msgs::GetPhysicsProperties::Request req;
  gazebo_msgs::GetPhysicsProperties::Response res;
  getPhysics(req, res);
  return res;
}

gazebo_msgs::ODEPhysics odeConfig(const bullet_sim::SolverSettings& solver) {
  gazebo_msgs::ODEPhysics ode = fixedOdeFields();
  ode.sor_pgs_iters = static_cast<uint32_t>(solver.iterations);
  ode.sor_pgs_w = solver.sor;
  ode.erp = solver.erp;
  ode.cfm = solver.cfm;
  return ode;
}

}  // namespace bullet_sim_node
