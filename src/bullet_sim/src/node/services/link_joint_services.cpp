#include "services/link_joint_services.h"

#include "topics/conversions.h"

#include <bullet_sim/description/model_properties.h>

#include <ros/console.h>

#include <cmath>
#include <optional>

namespace bullet_sim_node {
namespace {

std::string inQuotes(const std::string& s) { return "'" + s + "'"; }

std::string unknownLink(const std::string& field, const std::string& name) {
  return field + " " + inQuotes(name) + " is not a link (name it \"model::link\")";
}

std::string unknownFrame(const std::string& field, const std::string& name) {
  return field + " " + inQuotes(name) +
         " does not exist (use \"\" or \"world\", a model name or \"model::link\")";
}

std::string unknownJoint(const std::string& name) {
  return "joint " + inQuotes(name) + " does not exist (or is not revolute/continuous)";
}

/// The link an entity name names, if it names a link.
std::optional<bullet_sim::EntityName> findLink(const bullet_sim::Simulation& sim,
                                               const std::string& name) {
  std::optional<bullet_sim::EntityName> entity = sim.findEntity(name);
  if (entity && entity->link.empty()) return std::nullopt;
  return entity;
}

bullet_sim::ForceWindow windowOf(const ros::Time& start, const ros::Duration& duration) {
  return {start.toSec(), duration.toSec()};
}

}  // namespace

LinkJointServices::LinkJointServices(SimRunner& runner, const ros::NodeHandle& gazebo_nh)
    : runner_(runner) {
  ros::NodeHandle nh(gazebo_nh);
  servers_ = {
      nh.advertiseService("get_link_state", &LinkJointServices::getLinkState, this),
      nh.advertiseService("set_link_state", &LinkJointServices::setLinkState, this),
      nh.advertiseService("get_link_properties", &LinkJointServices::getLinkProperties, this),
      nh.advertiseService("get_joint_properties", &LinkJointServices::getJointProperties, this),
      nh.advertiseService("apply_body_wrench", &LinkJointServices::applyWrench, this),
      nh.advertiseService("apply_joint_effort", &LinkJointServices::applyEffort, this),
      nh.advertiseService("clear_body_wrenches", &LinkJointServices::clearWrenches, this),
      nh.advertiseService("clear_joint_forces", &LinkJointServices::clearEfforts, this),
  };
  set_state_sub_ = nh.subscribe("set_link_state", 10, &LinkJointServices::onSetLinkState, this);
}

bool LinkJointServices::getLinkState(gazebo_msgs::GetLinkState::Request& req,
                                     gazebo_msgs::GetLinkState::Response& res) {
  const bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> link = findLink(sim, req.link_name);
  const std::optional<bullet_sim::EntityState> frame = sim.frameState(req.reference_frame);
  if (!link) {
    res.status_message = "GetLinkState: " + unknownLink("link_name", req.link_name);
  } else if (!frame) {
    res.status_message = "GetLinkState: " + unknownFrame("reference_frame", req.reference_frame);
  } else {
    const bullet_sim::EntityState state = bullet_sim::expressIn(sim.entityState(*link), *frame);
    res.link_state.link_name = req.link_name;
    res.link_state.pose = toMsg(state.pose);
    res.link_state.twist = toMsg(state.twist);
    res.link_state.reference_frame = req.reference_frame;
    res.success = true;
    res.status_message = "GetLinkState: got state";
  }
  return true;
}

std::string LinkJointServices::applyLinkState(const gazebo_msgs::LinkState& state) {
  bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> link = findLink(sim, state.link_name);
  if (!link) return unknownLink("link_name", state.link_name);
  if (auto bad = firstNonFinite(state.pose)) return "pose " + *bad + " is not finite";
  if (auto bad = firstNonFinite(state.twist)) return "twist " + *bad + " is not finite";
  const std::optional<bullet_sim::EntityState> frame = sim.frameState(state.reference_frame);
  if (!frame) return unknownFrame("reference_frame", state.reference_frame);
  const bullet_sim::EntityState world = bullet_sim::stateInWorld(
      {fromMsg(state.pose), fromMsg(state.twist)}, frame->pose);
  sim.setLinkState(link->model, link->link, world.pose, world.twist);
  return "";
}

bool LinkJointServices::setLinkState(gazebo_msgs::SetLinkState::Request& req,
                                     gazebo_msgs::SetLinkState::Response& res) {
  const std::string error = applyLinkState(req.link_state);
  res.success = error.empty();
  res.status_message = res.success ? "SetLinkState: success" : "SetLinkState: " + error;
  return true;
}

void LinkJointServices::onSetLinkState(const gazebo_msgs::LinkState::ConstPtr& state) {
  const std::string error = applyLinkState(*state);
  if (!error.empty()) {
    ROS_WARN_THROTTLE(5.0, "%s: message dropped: %s", set_state_sub_.getTopic().c_str(),
                      error.c_str());
  }
}

bool LinkJointServices::getLinkProperties(gazebo_msgs::GetLinkProperties::Request& req,
                                          gazebo_msgs::GetLinkProperties::Response& res) {
  const std::optional<bullet_sim::EntityName> link = findLink(runner_.sim(), req.link_name);
  if (!link) {
    res.status_message = "GetLinkProperties: " + unknownLink("link_name", req.link_name);
    return true;
  }
  const bullet_sim::LinkProperties inertia =
      runner_.sim().linkProperties(link->model, link->link);
  res.com = toMsg(inertia.com_in_link);
  res.gravity_mode = inertia.gravity;
  res.mass = inertia.mass_kg;
  res.ixx = inertia.ixx;
  res.ixy = inertia.ixy;
  res.ixz = inertia.ixz;
  res.iyy = inertia.iyy;
  res.iyz = inertia.iyz;
  res.izz = inertia.izz;
  res.success = true;
  res.status_message = "GetLinkProperties: got properties";
  return true;
}

bool LinkJointServices::getJointProperties(gazebo_msgs::GetJointProperties::Request& req,
                                           gazebo_msgs::GetJointProperties::Response& res) {
  const bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> joint = sim.findJoint(req.joint_name);
  if (!joint) {
    res.status_message = "GetJointProperties: " + unknownJoint(req.joint_name);
    return true;
  }
  res.type = static_cast<uint8_t>(bullet_sim::jointKind(sim.robotSpec(joint->model), joint->link));
  res.position = {sim.jointPosition(joint->model, joint->link)};
  res.rate = {sim.jointVelocity(joint->model, joint->link)};
  res.success = true;
  res.status_message = "GetJointProperties: got properties";
  return true;
}

std::string LinkJointServices::queueWrench(const gazebo_msgs::ApplyBodyWrench::Request& req) {
  bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> link = findLink(sim, req.body_name);
  if (!link) return unknownLink("body_name", req.body_name);
  const std::optional<bullet_sim::EntityState> frame = sim.frameState(req.reference_frame);
  if (!frame) return unknownFrame("reference_frame", req.reference_frame);
  if (auto bad = firstNonFinite(req.wrench.force, "wrench.force")) return *bad + " is not finite";
  if (auto bad = firstNonFinite(req.wrench.torque, "wrench.torque")) return *bad + " is not finite";
  geometry_msgs::Vector3 point;
  point.x = req.reference_point.x;
  point.y = req.reference_point.y;
  point.z = req.reference_point.z;
  if (auto bad = firstNonFinite(point, "reference_point")) return *bad + " is not finite";
  bullet_sim::BodyWrench wrench;
  wrench.robot = link->model;
  wrench.link = link->link;
  wrench.wrench = bullet_sim::wrenchInWorld(
      fromMsg(req.wrench.force), fromMsg(req.wrench.torque), fromMsg(point),
      frame->pose.orientation);
  wrench.window = windowOf(req.start_time, req.duration);
  sim.externalForces().addWrench(wrench, sim.timeS());
  return "";
}

bool LinkJointServices::applyWrench(gazebo_msgs::ApplyBodyWrench::Request& req,
                                    gazebo_msgs::ApplyBodyWrench::Response& res) {
  const std::string error = queueWrench(req);
  res.success = error.empty();
  res.status_message = res.success ? "ApplyBodyWrench: wrench set" : "ApplyBodyWrench: " + error;
  return true;
}

bool LinkJointServices::applyEffort(gazebo_msgs::ApplyJointEffort::Request& req,
                                    gazebo_msgs::ApplyJointEffort::Response& res) {
  bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> joint = sim.findJoint(req.joint_name);
  res.success = false;
  if (!joint) {
    res.status_message = "ApplyJointEffort: " + unknownJoint(req.joint_name);
  } else if (!std::isfinite(req.effort)) {
    res.status_message = "ApplyJointEffort: effort " + std::to_string(req.effort) +
                         " is not finite";
  } else {
    sim.externalForces().addEffort(
        {joint->model, joint->link, req.effort, windowOf(req.start_time, req.duration)},
        sim.timeS());
    res.success = true;
    res.status_message = "ApplyJointEffort: effort set";
  }
  return true;
}

bool LinkJointServices::clearWrenches(gazebo_msgs::BodyRequest::Request& req,
                                      gazebo_msgs::BodyRequest::Response&) {
  const std::optional<bullet_sim::EntityName> link = findLink(runner_.sim(), req.body_name);
  if (!link) {
    ROS_ERROR("ClearBodyWrenches: %s", unknownLink("body_name", req.body_name).c_str());
    return false;
  }
  runner_.sim().externalForces().clearWrenches(link->model, link->link);
  return true;
}

bool LinkJointServices::clearEfforts(gazebo_msgs::JointRequest::Request& req,
                                     gazebo_msgs::JointRequest::Response&) {
  bullet_sim::Simulation& sim = runner_.sim();
  const std::optional<bullet_sim::EntityName> joint = sim.findJoint(req.joint_name);
  if (!joint) {
    ROS_ERROR("ClearJointForces: %s", unknownJoint(req.joint_name).c_str());
    return false;
  }
  if (joint->link != req.joint_name) {  // scoped: that model's joint only
    sim.externalForces().clearEfforts(joint->model, joint->link);
    return true;
  }
  // A bare name: that joint in every model, as Gazebo clears by joint name.
  for (const std::string& model : sim.robotNames()) {
    sim.externalForces().clearEfforts(model, req.joint_name);
  }
  return true;
}

}  // namespace bullet_sim_node
