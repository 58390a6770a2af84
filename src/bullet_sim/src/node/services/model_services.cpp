#include "services/model_services.h"

#include "topics/conversions.h"

#include <bullet_sim/errors.h>
#include <bullet_sim/description/model_properties.h>
#include <bullet_sim/description/robot_spec.h>

#include <ros/console.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace bullet_sim_node {
namespace {

enum class ModelFormat { Urdf, Sdf, Unknown };

/// What the document's root element says it is (<robot>: URDF; <sdf>, or <gazebo> as
/// old SDF files start: SDF).
/// URDF or SDF by the root element; `why` says what else the text is.
ModelFormat formatOf(const std::string& xml, std::string* why) {
  tinyxml2::XMLDocument doc;
  if (xml.empty()) {
    *why = "it is empty";
    return ModelFormat::Unknown;
  }
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS || !doc.RootElement()) {
    *why = std::string("it is not well-formed XML: ") + doc.ErrorStr();
    return ModelFormat::Unknown;
  }
  *why = "its root element is <" + std::string(doc.RootElement()->Name()) + ">";
  const std::string root = doc.RootElement()->Name();
  if (root == "robot") return ModelFormat::Urdf;
  if (root == "sdf" || root == "gazebo") return ModelFormat::Sdf;
  return ModelFormat::Unknown;
}

std::string inQuotes(const std::string& s) { return "'" + s + "'"; }

/// The static world model of that name, if there is one.
const bullet_sim::StaticModel* staticModel(const bullet_sim::Simulation& sim,
                                           const std::string& name) {
  for (const bullet_sim::StaticModel& model : sim.world().static_models)
    if (model.name == name) return &model;
  return nullptr;
}

std::string staticRefused(const std::string& name, const std::string& what) {
  return "model " + inQuotes(name) + " is a static model of the world file: it cannot be " +
         what + " here";
}

std::string unknownFrame(const std::string& field, const std::string& name) {
  return field + " " + inQuotes(name) +
         " does not exist (use \"\" or \"world\", a model name or \"model::link\")";
}

}  // namespace

ModelServices::ModelServices(SimRunner& runner, const ros::NodeHandle& gazebo_nh,
                             bool spawn_model_service)
    : runner_(runner) {
  ros::NodeHandle nh(gazebo_nh);
  servers_ = {
      nh.advertiseService("spawn_urdf_model", &ModelServices::spawn, this),
      nh.advertiseService("spawn_sdf_model", &ModelServices::spawn, this),
      nh.advertiseService("delete_model", &ModelServices::remove, this),
      nh.advertiseService("get_model_state", &ModelServices::getState, this),
      nh.advertiseService("set_model_state", &ModelServices::setState, this),
      nh.advertiseService("get_world_properties", &ModelServices::getWorld, this),
      nh.advertiseService("get_model_properties", &ModelServices::getProperties, this),
      nh.advertiseService("set_model_configuration", &ModelServices::setConfiguration, this),
  };
  if (spawn_model_service) {
    servers_.push_back(nh.advertiseService("spawn_model", &ModelServices::spawn, this));
  }
  set_state_sub_ = nh.subscribe("set_model_state", 10, &ModelServices::onSetState, this);
}

bool ModelServices::hasModel(const std::string& name) const {
  const std::vector<std::string> names = runner_.sim().robotNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string ModelServices::spawnModel(const gazebo_msgs::SpawnModel::Request& req) {
  if (req.model_name.empty()) return "model_name is empty";
  if (req.model_name.find("::") != std::string::npos)
    return "model_name " + inQuotes(req.model_name) + " contains '::' (the link separator)";
  if (hasModel(req.model_name) || staticModel(runner_.sim(), req.model_name))
    return "model " + inQuotes(req.model_name) + " already exists";
  if (auto bad = firstNonFinite(req.initial_pose)) return "initial_pose " + *bad + " is not finite";
  const std::optional<bullet_sim::EntityState> frame =
      runner_.sim().frameState(req.reference_frame);
  if (!frame) return unknownFrame("reference_frame", req.reference_frame);
  std::string why;
  const ModelFormat format = formatOf(req.model_xml, &why);
  if (format == ModelFormat::Unknown) {
    return "model_xml of " + inQuotes(req.model_name) +
           " is neither URDF (<robot>) nor SDF (<sdf>): " + why;
  }
  try {
    const bullet_sim::RobotSpec spec =
        format == ModelFormat::Urdf ? bullet_sim::parseRobot(req.model_xml, req.model_name)
                                    : bullet_sim::parseSdfModelString(req.model_xml,
                                                                      req.model_name);
    for (const std::string& warning : spec.warnings)
      ROS_WARN("model %s: %s", req.model_name.c_str(), warning.c_str());
    bullet_sim::EntityState relative;
    relative.pose = fromMsg(req.initial_pose);
    runner_.spawn(req.model_name, spec, bullet_sim::stateInWorld(relative, frame->pose).pose,
                  req.robot_namespace);
  } catch (const bullet_sim::LoadError& error) {
    return error.what();
  } catch (const ros::InvalidNameException& error) {
    return "model " + inQuotes(req.model_name) + " in robot_namespace " +
           inQuotes(req.robot_namespace) + ": " + error.what();
  }
  return "";
}

bool ModelServices::spawn(gazebo_msgs::SpawnModel::Request& req,
                          gazebo_msgs::SpawnModel::Response& res) {
  const std::string error = spawnModel(req);
  res.success = error.empty();
  res.status_message = res.success ? "SpawnModel: successfully spawned model " + req.model_name
                                   : "SpawnModel: " + error;
  if (!res.success) ROS_ERROR("%s", res.status_message.c_str());
  return true;
}

bool ModelServices::remove(gazebo_msgs::DeleteModel::Request& req,
                           gazebo_msgs::DeleteModel::Response& res) {
  if (staticModel(runner_.sim(), req.model_name)) {
    res.success = false;
    res.status_message = "DeleteModel: " + staticRefused(req.model_name, "deleted");
    return true;
  }
  res.success = runner_.remove(req.model_name);
  res.status_message = res.success
                           ? "DeleteModel: successfully deleted model " + req.model_name
                           : "DeleteModel: model " + inQuotes(req.model_name) + " does not exist";
  return true;
}

bool ModelServices::getState(gazebo_msgs::GetModelState::Request& req,
                             gazebo_msgs::GetModelState::Response& res) {
  const bullet_sim::Simulation& sim = runner_.sim();
  res.header.stamp.fromSec(sim.timeS());
  res.header.frame_id = req.relative_entity_name;
  const std::optional<bullet_sim::EntityState> frame = sim.frameState(req.relative_entity_name);
  const bullet_sim::StaticModel* fixed = staticModel(sim, req.model_name);
  if (!hasModel(req.model_name) && !fixed) {
    res.status_message = "GetModelState: model " + inQuotes(req.model_name) + " does not exist";
  } else if (!frame) {
    res.status_message = "GetModelState: " +
                         unknownFrame("relative_entity_name", req.relative_entity_name);
  } else {
    const bullet_sim::EntityState state = bullet_sim::expressIn(
        fixed ? bullet_sim::EntityState{fixed->pose, bullet_sim::Twist3{}}
              : sim.entityState({req.model_name, ""}),
        *frame);
    res.pose = toMsg(state.pose);
    res.twist = toMsg(state.twist);
    res.success = true;
    res.status_message = "GetModelState: got properties";
  }
  return true;
}

std::string ModelServices::applyState(const gazebo_msgs::ModelState& state) {
  if (staticModel(runner_.sim(), state.model_name)) return staticRefused(state.model_name, "moved");
  if (!hasModel(state.model_name)) return "model " + inQuotes(state.model_name) + " does not exist";
  if (auto bad = firstNonFinite(state.pose)) return "pose " + *bad + " is not finite";
  if (auto bad = firstNonFinite(state.twist)) return "twist " + *bad + " is not finite";
  const std::optional<bullet_sim::EntityState> frame =
      runner_.sim().frameState(state.reference_frame);
  if (!frame) return unknownFrame("reference_frame", state.reference_frame);
  bullet_sim::EntityState relative{fromMsg(state.pose), fromMsg(state.twist)};
  const bullet_sim::EntityState world = bullet_sim::stateInWorld(relative, frame->pose);
  runner_.sim().setModelState(state.model_name, world.pose, world.twist);
  return "";
}

bool ModelServices::setState(gazebo_msgs::SetModelState::Request& req,
                             gazebo_msgs::SetModelState::Response& res) {
  const std::string error = applyState(req.model_state);
  res.success = error.empty();
  res.status_message = res.success ? "SetModelState: set model state done"
                                   : "SetModelState: " + error;
  return true;
}

void ModelServices::onSetState(const gazebo_msgs::ModelState::ConstPtr& state) {
  const std::string error = applyState(*state);
  if (!error.empty()) {
    ROS_WARN_THROTTLE(5.0, "%s: message dropped: %s", set_state_sub_.getTopic().c_str(),
                      error.c_str());
  }
}

bool ModelServices::getWorld(gazebo_msgs::GetWorldProperties::Request&,
                             gazebo_msgs::GetWorldProperties::Response& res) {
  res.sim_time = runner_.sim().timeS();
  // As Gazebo lists them: the world file's models, then the spawned ones in spawn order.
  for (const bullet_sim::StaticModel& model : runner_.sim().world().static_models)
    res.model_names.push_back(model.name);
  const std::vector<std::string> moving = runner_.sim().robotNames();
  res.model_names.insert(res.model_names.end(), moving.begin(), moving.end());
  res.rendering_enabled = true;
  res.success = true;
  res.status_message = "GetWorldProperties: got properties";
  return true;
}

bool ModelServices::getProperties(gazebo_msgs::GetModelProperties::Request& req,
                                  gazebo_msgs::GetModelProperties::Response& res) {
  if (!hasModel(req.model_name)) {
    res.status_message =
        "GetModelProperties: model " + inQuotes(req.model_name) + " does not exist";
    return true;
  }
  const bullet_sim::Simulation& sim = runner_.sim();
  res.canonical_body_name = sim.rootLink(req.model_name);
  res.body_names = sim.linkNames(req.model_name);
  res.geom_names = bullet_sim::collisionNames(sim.robotSpec(req.model_name));
  res.joint_names = sim.jointNames(req.model_name);
  res.is_static = sim.robotSpec(req.model_name).is_static;
  res.success = true;
  res.status_message = "GetModelProperties: got properties";
  return true;
}

bool ModelServices::setConfiguration(gazebo_msgs::SetModelConfiguration::Request& req,
                                     gazebo_msgs::SetModelConfiguration::Response& res) {
  res.success = false;
  if (!hasModel(req.model_name)) {
    res.status_message =
        "SetModelConfiguration: model " + inQuotes(req.model_name) + " does not exist";
    return true;
  }
  if (req.joint_names.size() != req.joint_positions.size()) {
    res.status_message = "SetModelConfiguration: " + std::to_string(req.joint_names.size()) +
                         " joint_names but " + std::to_string(req.joint_positions.size()) +
                         " joint_positions";
    return true;
  }
  std::map<std::string, double> positions;
  for (size_t i = 0; i < req.joint_names.size(); ++i) {
    if (!std::isfinite(req.joint_positions[i])) {
      res.status_message = "SetModelConfiguration: position of joint " +
                           inQuotes(req.joint_names[i]) + " is not finite";
      return true;
    }
    positions[req.joint_names[i]] = req.joint_positions[i];
  }
  try {
    runner_.sim().setJointPositions(req.model_name, positions);
  } catch (const std::out_of_range& error) {
    res.status_message = std::string("SetModelConfiguration: ") + error.what();
    return true;
  }
  res.success = true;
  res.status_message = "SetModelConfiguration: success";
  return true;
}

}  // namespace bullet_sim_node
