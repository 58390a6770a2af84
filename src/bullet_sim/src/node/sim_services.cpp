#include "sim_services.h"

#include "conversions.h"

#include <bullet_sim/errors.h>
#include <bullet_sim/robot_spec.h>

#include <algorithm>

namespace bullet_sim_node {
namespace {

bool isWorldFrame(const std::string& frame) { return frame.empty() || frame == "world"; }

}  // namespace

SimServices::SimServices(SimRunner& runner, const ros::NodeHandle& nh) : runner_(runner) {
  ros::NodeHandle handle(nh);
  servers_ = {
      handle.advertiseService("pause_physics", &SimServices::pause, this),
      handle.advertiseService("unpause_physics", &SimServices::unpause, this),
      handle.advertiseService("reset_simulation", &SimServices::resetSimulation, this),
      handle.advertiseService("reset_world", &SimServices::resetWorld, this),
      handle.advertiseService("step_simulation", &SimServices::step, this),
      handle.advertiseService("spawn_urdf_model", &SimServices::spawn, this),
      handle.advertiseService("spawn_model", &SimServices::spawn, this),
      handle.advertiseService("delete_model", &SimServices::remove, this),
      handle.advertiseService("get_model_state", &SimServices::getState, this),
      handle.advertiseService("set_model_state", &SimServices::setState, this),
  };
}

bool SimServices::hasRobot(const std::string& name) const {
  const std::vector<std::string> names = runner_.sim().robotNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool SimServices::pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  runner_.setPaused(true);
  return true;
}

bool SimServices::unpause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  runner_.setPaused(false);
  return true;
}

bool SimServices::resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  runner_.sim().reset();
  runner_.publishClock();
  return true;
}

bool SimServices::resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  for (const std::string& robot : runner_.sim().robotNames()) {
    runner_.sim().setCmdVel(robot, 0, 0);
    runner_.sim().setModelState(robot, runner_.spawnPose(robot), bullet_sim::Twist3{});
  }
  return true;
}

bool SimServices::step(bullet_sim::StepSimulation::Request& req,
                       bullet_sim::StepSimulation::Response& res) {
  if (!runner_.paused()) {
    res.status_message = "physics is running: call pause_physics before stepping";
  } else {
    for (uint32_t i = 0; i < req.steps; ++i) runner_.step();
    runner_.publishClock();
    res.success = true;
    res.status_message = "stepped " + std::to_string(req.steps) + " steps";
  }
  res.sim_time.fromSec(runner_.sim().timeS());
  return true;
}

bool SimServices::spawn(bullet_sim::SpawnModel::Request& req,
                        bullet_sim::SpawnModel::Response& res) {
  if (!isWorldFrame(req.reference_frame)) {
    res.status_message = "reference_frame '" + req.reference_frame +
                         "' is not supported: use \"\" or \"world\"";
    return true;
  }
  try {
    const bullet_sim::RobotSpec spec = bullet_sim::parseRobot(req.model_xml, req.model_name);
    for (const std::string& warning : spec.warnings)
      ROS_WARN("model %s: %s", req.model_name.c_str(), warning.c_str());
    runner_.spawn(req.model_name, spec, fromMsg(req.initial_pose), req.robot_namespace);
    res.success = true;
    res.status_message = "spawned " + req.model_name;
  } catch (const bullet_sim::LoadError& error) {
    res.status_message = error.what();
  }
  return true;
}

bool SimServices::remove(bullet_sim::DeleteModel::Request& req,
                         bullet_sim::DeleteModel::Response& res) {
  res.success = runner_.remove(req.model_name);
  res.status_message = res.success ? "deleted " + req.model_name
                                   : "no model named '" + req.model_name + "'";
  return true;
}

bool SimServices::getState(bullet_sim::GetModelState::Request& req,
                           bullet_sim::GetModelState::Response& res) {
  res.header.stamp.fromSec(runner_.sim().timeS());
  res.header.frame_id = "world";
  if (!hasRobot(req.model_name)) {
    res.status_message = "no model named '" + req.model_name + "'";
  } else if (!isWorldFrame(req.relative_entity_name)) {
    res.status_message = "relative_entity_name '" + req.relative_entity_name +
                         "' is not supported: use \"\" or \"world\"";
  } else {
    res.pose = toMsg(runner_.sim().modelPose(req.model_name));
    res.twist = toMsg(runner_.sim().modelTwist(req.model_name));
    res.success = true;
    res.status_message = "ok";
  }
  return true;
}

bool SimServices::setState(bullet_sim::SetModelState::Request& req,
                           bullet_sim::SetModelState::Response& res) {
  const bullet_sim::ModelState& state = req.model_state;
  if (!hasRobot(state.model_name)) {
    res.status_message = "no model named '" + state.model_name + "'";
  } else if (!isWorldFrame(state.reference_frame)) {
    res.status_message = "reference_frame '" + state.reference_frame +
                         "' is not supported: use \"\" or \"world\"";
  } else {
    runner_.sim().setModelState(state.model_name, fromMsg(state.pose), fromMsg(state.twist));
    res.success = true;
    res.status_message = "ok";
  }
  return true;
}

}  // namespace bullet_sim_node
