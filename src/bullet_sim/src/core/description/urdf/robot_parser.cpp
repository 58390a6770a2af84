#include <filesystem>
#include <fstream>
#include <sstream>

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "description/description_geometry.h"
#include "description/gazebo/gazebo_extensions.h"
#include "description/urdf/robot_parser.h"
#include "description/urdf/urdf_checks.h"

namespace bullet_sim {
namespace {

/// Collects urdfdom's console_bridge errors while it parses, so that the
/// LoadError can carry the parser's own reason.
class CapturedLog : public console_bridge::OutputHandler {
 public:
  CapturedLog() { console_bridge::useOutputHandler(this); }
  ~CapturedLog() override { console_bridge::restorePreviousOutputHandler(); }
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      errors_ += (errors_.empty() ? "" : "; ") + text;
    }
  }
  const std::string& errors() const { return errors_; }

 private:
  std::string errors_;
};

Pose3 toPose(const urdf::Pose& p) {
  Pose3 out;
  out.position = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  out.orientation = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  return out;
}

}  // namespace

void addLinkVisuals(const urdf::Link& link, RobotSpec* spec) {
  for (const urdf::VisualSharedPtr& v : link.visual_array) {
    if (!v || !v->geometry) continue;
    VisualSpec vis;
    vis.geometry() = geometryOf(*v->geometry);
    vis.link = link.name;
    vis.pose_in_link = toPose(v->origin);
    if (v->material) {
      const urdf::Color& c = v->material->color;
      vis.rgba = Eigen::Vector4f(c.r, c.g, c.b, c.a);
    }
    spec->visuals.push_back(vis);
  }
}

namespace {

/// The folder relative mesh names start from: the robot file's, else the current one.
std::string baseDirOf(const std::string& source_name) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(source_name, ec)) return "";
  return std::filesystem::path(source_name).parent_path().string();
}

/// The joints of a URDF document as written, before urdfdom builds (or fails to build) its
/// tree: a loop that leaves no root link gets only "No root link found" from urdfdom.
std::vector<JointEdge> jointEdgesOf(const tinyxml2::XMLDocument& urdf) {
  std::vector<JointEdge> joints;
  const tinyxml2::XMLElement* robot = urdf.FirstChildElement("robot");
  for (const tinyxml2::XMLElement* j = robot ? robot->FirstChildElement("joint") : nullptr; j;
       j = j->NextSiblingElement("joint")) {
    const tinyxml2::XMLElement* parent = j->FirstChildElement("parent");
    const tinyxml2::XMLElement* child = j->FirstChildElement("child");
    const char* name = j->Attribute("name");
    const char* parent_link = parent ? parent->Attribute("link") : nullptr;
    const char* child_link = child ? child->Attribute("link") : nullptr;
    if (name && parent_link && child_link) joints.push_back({name, parent_link, child_link});
  }
  return joints;
}

}  // namespace

RobotSpec parseRobot(const std::string& urdf_xml, const std::string& source_name) {
  return parseRobot(urdf_xml, source_name, UriResolver(ResourcePaths::fromEnvironment()));
}

RobotSpec parseRobot(const std::string& urdf_xml, const std::string& source_name,
                     const UriResolver& resolver) {
  RobotSpec spec;
  // urdfdom says "Error document empty." for any text that is not XML: tinyxml2 says where.
  tinyxml2::XMLDocument xml;
  if (xml.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS) {
    throw LoadError(source_name + ": invalid URDF: not well-formed XML: " + xml.ErrorStr());
  }
  checkTree(jointEdgesOf(xml), source_name);
  {
    CapturedLog log;
    spec.urdf = urdf::parseURDF(urdf_xml);
    // urdfdom logs some errors and carries on without the element (a collision whose origin
    // has a nan is left out, an inertia with one becomes zero): that would be a half-load.
    if (!spec.urdf || !log.errors().empty()) {
      throw LoadError(source_name + ": invalid URDF: " +
                      (log.errors().empty() ? "urdfdom could not parse it" : log.errors()));
    }
  }
  checkUrdfModel(*spec.urdf, source_name);
  spec.name = spec.urdf->getName();
  std::vector<urdf::LinkSharedPtr> links;
  spec.urdf->getLinks(links);
  for (const urdf::LinkSharedPtr& link : links) {
    if (!link->collision_array.empty() && !link->inertial) {
      spec.warnings.push_back("link '" + link->name +
                              "' has <collision> but no <inertial>: it is given no mass "
                              "(Gazebo would drop it)");
    }
    addLinkVisuals(*link, &spec);
  }
  loadRobotMeshes(resolver, baseDirOf(source_name), source_name, &spec);
  parseGazeboExtensions(urdf_xml, source_name, &spec);
  for (const auto& surface : spec.surfaces) {
    if (!spec.urdf->getLink(surface.first)) {
      spec.warnings.push_back("<gazebo reference=\"" + surface.first +
                              "\"> names no link: its surface parameters are ignored");
    }
  }
  return spec;
}

RobotSpec parseRobotFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw LoadError(path + ": cannot read the robot file");
  std::stringstream text;
  text << in.rdbuf();
  return parseRobot(text.str(), path);
}

}  // namespace bullet_sim
