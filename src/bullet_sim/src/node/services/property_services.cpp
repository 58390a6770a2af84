#include "services/property_services.h"

#include "topics/conversions.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace bullet_sim_node {
namespace {

const bullet_sim::LightSpec* findLight(const bullet_sim::Simulation& sim, const std::string& name) {
  for (const bullet_sim::LightSpec& light : sim.world().lights) {
    if (light.name == name) return &light;
  }
  return nullptr;
}

std::string unknownLight(const std::string& name) {
  return "light '" + name + "' does not exist (the world's <light> names)";
}

std::optional<std::string> nonFiniteColour(const std_msgs::ColorRGBA& c, const std::string& name) {
  const float values[] = {c.r, c.g, c.b, c.a};
  const char* fields[] = {"r", "g", "b", "a"};
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(values[i])) {
      return name + "." + fields[i] + " = " + std::to_string(values[i]) + " is not finite";
    }
  }
  return std::nullopt;
}

/// The light `req` describes, from `light` as it is; or why it cannot be.
std::string applyLightRequest(const gazebo_msgs::SetLightProperties::Request& req,
                              bullet_sim::LightSpec* light) {
  if (auto bad = nonFiniteColour(req.diffuse, "diffuse")) return *bad;
  if (auto bad = nonFiniteColour(req.specular, "specular")) return *bad;
  if (auto bad = firstNonFinite(req.pose)) return "pose " + *bad + " is not finite";
  if (auto bad = firstNonFinite(req.direction, "direction")) return *bad + " is not finite";
  for (double a : {req.attenuation_constant, req.attenuation_linear, req.attenuation_quadratic}) {
    if (!(std::isfinite(a) && a >= 0)) {
      return "attenuation " + std::to_string(a) + " must be finite and >= 0";
    }
  }
  const bullet_sim::Pose3 pose = fromMsg(req.pose);
  const Eigen::Vector3d direction = fromMsg(req.direction);
  if (light->type != "point" && direction.norm() < 1e-12) {
    return "direction (0, 0, 0) has no length (a " + light->type + " light points somewhere)";
  }
  light->cast_shadows = req.cast_shadows;
  light->diffuse = {req.diffuse.r, req.diffuse.g, req.diffuse.b, req.diffuse.a};
  light->specular = {req.specular.r, req.specular.g, req.specular.b, req.specular.a};
  light->constant = req.attenuation_constant;
  light->linear = req.attenuation_linear;
  light->quadratic = req.attenuation_quadratic;
  light->pose = pose;
  // As in SDF and Gazebo's light message, the direction is in the light's frame.
  if (direction.norm() >= 1e-12) light->direction = (pose.orientation * direction).normalized();
  return "";
}

/// An ODE joint array of at most one value (a hinge has one axis) as an optional.
std::optional<double> axisValue(const std::vector<double>& values, const std::string& field) {
  if (values.size() > 1) {
    throw std::invalid_argument(field + " has " + std::to_string(values.size()) +
                                " values: a revolute joint has one axis (index 0)");
  }
  if (values.empty()) return std::nullopt;
  return values[0];
}

bullet_sim::JointDynamics dynamicsOf(const gazebo_msgs::ODEJointProperties& ode) {
  if (!ode.fudge_factor.empty()) {
    throw std::invalid_argument("fudge_factor has no equivalent in Bullet's hinge (leave it empty)");
  }
  bullet_sim::JointDynamics d;
  d.damping_nms_per_rad = axisValue(ode.damping, "damping");
  d.upper_rad = axisValue(ode.hiStop, "hiStop");
  d.lower_rad = axisValue(ode.loStop, "loStop");
  d.erp = axisValue(ode.erp, "erp");
  d.cfm = axisValue(ode.cfm, "cfm");
  d.stop_erp = axisValue(ode.stop_erp, "stop_erp");
  d.stop_cfm = axisValue(ode.stop_cfm, "stop_cfm");
  d.motor_max_torque_nm = axisValue(ode.fmax, "fmax");
  d.motor_velocity_radps = axisValue(ode.vel, "vel");
  return d;
}

}  // namespace

PropertyServices::PropertyServices(SimRunner& runner, const ros::NodeHandle& gazebo_nh)
    : runner_(runner) {
  ros::NodeHandle nh(gazebo_nh);
  servers_ = {
      nh.advertiseService("delete_light", &PropertyServices::deleteLight, this),
      nh.advertiseService("get_light_properties", &PropertyServices::getLight, this),
      nh.advertiseService("set_light_properties", &PropertyServices::setLight, this),
      nh.advertiseService("set_link_properties", &PropertyServices::setLink, this),
      nh.advertiseService("set_joint_properties", &PropertyServices::setJoint, this),
  };
}

bool PropertyServices::deleteLight(gazebo_msgs::DeleteLight::Request& req,
                                   gazebo_msgs::DeleteLight::Response& res) {
  res.success = runner_.sim().deleteLight(req.light_name);
  res.status_message = res.success ? "DeleteLight: " + req.light_name + " successfully deleted"
                                   : "DeleteLight: " + unknownLight(req.light_name);
  return true;
}

bool PropertyServices::getLight(gazebo_msgs::GetLightProperties::Request& req,
                                gazebo_msgs::GetLightProperties::Response& res) {
  const bullet_sim::LightSpec* light = findLight(runner_.sim(), req.light_name);
  if (!light) {
    res.status_message = "GetLightProperties: " + unknownLight(req.light_name);
    return true;
  }
  res.diffuse.r = light->diffuse[0];
  res.diffuse.g = light->diffuse[1];
  res.diffuse.b = light->diffuse[2];
  res.diffuse.a = light->diffuse[3];
  res.attenuation_constant = light->constant;
  res.attenuation_linear = light->linear;
  res.attenuation_quadratic = light->quadratic;
  res.success = true;
  res.status_message = "GetLightProperties: got properties";
  return true;
}

bool PropertyServices::setLight(gazebo_msgs::SetLightProperties::Request& req,
                                gazebo_msgs::SetLightProperties::Response& res) {
  const bullet_sim::LightSpec* current = findLight(runner_.sim(), req.light_name);
  if (!current) {
    res.status_message = "SetLightProperties: " + unknownLight(req.light_name);
    return true;
  }
  bullet_sim::LightSpec light = *current;
  const std::string error = applyLightRequest(req, &light);
  res.success = error.empty() && runner_.sim().setLight(light);
  res.status_message = res.success ? "SetLightProperties: properties set"
                                   : "SetLightProperties: " + error;
  return true;
}

bool PropertyServices::setLink(gazebo_msgs::SetLinkProperties::Request& req,
                               gazebo_msgs::SetLinkProperties::Response& res) {
  bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> link = sim.findEntity(req.link_name);
  if (!link || link->link.empty()) {
    res.status_message = "SetLinkProperties: link_name '" + req.link_name +
                         "' is not a link (name it \"model::link\")";
    return true;
  }
  bullet_sim::LinkProperties p;
  p.mass_kg = req.mass;
  p.com_in_link = fromMsg(req.com);
  p.ixx = req.ixx;
  p.ixy = req.ixy;
  p.ixz = req.ixz;
  p.iyy = req.iyy;
  p.iyz = req.iyz;
  p.izz = req.izz;
  p.gravity = req.gravity_mode;
  try {
    sim.setLinkProperties(link->model, link->link, p);
    res.success = true;
    res.status_message = "SetLinkProperties: properties set";
  } catch (const std::invalid_argument& error) {
    res.status_message = "SetLinkProperties: " + req.link_name + ": " + error.what();
  }
  return true;
}

bool PropertyServices::setJoint(gazebo_msgs::SetJointProperties::Request& req,
                                gazebo_msgs::SetJointProperties::Response& res) {
  bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> joint = sim.findJoint(req.joint_name);
  if (!joint) {
    res.status_message = "SetJointProperties: joint '" + req.joint_name +
                         "' does not exist (or is not revolute/continuous)";
    return true;
  }
  try {
    sim.setJointDynamics(joint->model, joint->link, dynamicsOf(req.ode_joint_config));
    res.success = true;
    res.status_message = "SetJointProperties: properties set";
  } catch (const std::invalid_argument& error) {
    res.status_message = "SetJointProperties: " + req.joint_name + ": " + error.what();
  }
  return true;
}

}  // namespace bullet_sim_node
