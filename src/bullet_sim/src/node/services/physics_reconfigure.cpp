#include "services/physics_reconfigure.h"

#include <ros/console.h>

#include <string>

namespace bullet_sim_node {
namespace {

bullet_sim::PhysicsConfig configOf(const gazebo_msgs::GetPhysicsProperties::Response& p) {
  bullet_sim::PhysicsConfig config;
  config.time_step = p.time_step;
  config.max_update_rate = p.max_update_rate;
  config.gravity_x = p.gravity.x;
  config.gravity_y = p.gravity.y;
  config.gravity_z = p.gravity.z;
  config.auto_disable_bodies = p.ode_config.auto_disable_bodies;
  config.sor_pgs_precon_iters = static_cast<int>(p.ode_config.sor_pgs_precon_iters);
  config.sor_pgs_iters = static_cast<int>(p.ode_config.sor_pgs_iters);
  config.sor_pgs_w = p.ode_config.sor_pgs_w;
  config.sor_pgs_rms_error_tol = p.ode_config.sor_pgs_rms_error_tol;
  config.cfm = p.ode_config.cfm;
  config.erp = p.ode_config.erp;
  config.contact_surface_layer = p.ode_config.contact_surface_layer;
  config.contact_max_correcting_vel = p.ode_config.contact_max_correcting_vel;
  config.max_contacts = static_cast<int>(p.ode_config.max_contacts);
  return config;
}

gazebo_msgs::SetPhysicsProperties::Request requestOf(const bullet_sim::PhysicsConfig& c) {
  gazebo_msgs::SetPhysicsProperties::Request req;
  req.time_step = c.time_step;
  req.max_update_rate = c.max_update_rate;
  req.gravity.x = c.gravity_x;
  req.gravity.y = c.gravity_y;
  req.gravity.z = c.gravity_z;
  req.ode_config.auto_disable_bodies = c.auto_disable_bodies;
  req.ode_config.sor_pgs_precon_iters = static_cast<uint32_t>(c.sor_pgs_precon_iters);
  req.ode_config.sor_pgs_iters = static_cast<uint32_t>(c.sor_pgs_iters);
  req.ode_config.sor_pgs_w = c.sor_pgs_w;
  req.ode_config.sor_pgs_rms_error_tol = c.sor_pgs_rms_error_tol;
  req.ode_config.cfm = c.cfm;
  req.ode_config.erp = c.erp;
  req.ode_config.contact_surface_layer = c.contact_surface_layer;
  req.ode_config.contact_max_correcting_vel = c.contact_max_correcting_vel;
  req.ode_config.max_contacts = static_cast<uint32_t>(c.max_contacts);
  return req;
}

/// Puts back, with a warning, a field Bullet has no counterpart for.
template <typename T>
void keep(T* value, T current, const char* name) {
  if (*value == current) return;
  ROS_WARN_STREAM("physics parameter " << name << " = " << *value
                  << " has no equivalent in Bullet: it stays " << current);
  *value = current;
}

}  // namespace

PhysicsReconfigure::PhysicsReconfigure(PhysicsServices& physics, const ros::NodeHandle& gazebo_nh)
    : physics_(physics), server_(mutex_, gazebo_nh) {
  server_.setCallback([this](bullet_sim::PhysicsConfig& config, uint32_t level) {
    onReconfigure(config, level);
  });
}

void PhysicsReconfigure::publishCurrent() { server_.updateConfig(configOf(physics_.currentPhysics())); }

void PhysicsReconfigure::onReconfigure(bullet_sim::PhysicsConfig& config, uint32_t) {
  const bullet_sim::PhysicsConfig current = configOf(physics_.currentPhysics());
  if (!initialized_) {
    // The parameters start as the simulation is (its world's step and gravity, the
    // real-time factor), not as the .cfg's defaults, as gazebo_ros's server does.
    initialized_ = true;
    config = current;
    return;
  }
  keep(&config.auto_disable_bodies, current.auto_disable_bodies, "auto_disable_bodies");
  keep(&config.sor_pgs_precon_iters, current.sor_pgs_precon_iters, "sor_pgs_precon_iters");
  keep(&config.sor_pgs_rms_error_tol, current.sor_pgs_rms_error_tol, "sor_pgs_rms_error_tol");
  keep(&config.contact_surface_layer, current.contact_surface_layer, "contact_surface_layer");
  keep(&config.contact_max_correcting_vel, current.contact_max_correcting_vel,
       "contact_max_correcting_vel");
  keep(&config.max_contacts, current.max_contacts, "max_contacts");
  const std::string error = physics_.applyPhysics(requestOf(config));
  if (!error.empty()) ROS_WARN("physics parameters not changed: %s", error.c_str());
  config = configOf(physics_.currentPhysics());
}

}  // namespace bullet_sim_node
