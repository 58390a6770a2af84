#include "description/gazebo/body_plugin_reader.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "description/gazebo/gazebo_values.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// "x y z" of child `name`, (0, 0, 0) when it is absent.
Eigen::Vector3d vector3(const XmlValues& xml, const XMLElement* p, const char* name,
                        const std::string& where) {
  const std::string s = xml.text(p, name, "0 0 0");
  std::istringstream in(s);
  std::vector<double> v;
  std::string token;
  while (in >> token) {
    double d = 0;
    if (!parseNumber(token, &d) || !std::isfinite(d)) {
      xml.fail(where + " <" + name + ">", "'" + s + "' is not three numbers");
    }
    v.push_back(d);
  }
  if (v.size() != 3) xml.fail(where + " <" + name + ">", "'" + s + "' is not three numbers");
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

std::string required(const XmlValues& xml, const XMLElement* p, const char* name,
                     const std::string& where) {
  const std::string value = xml.text(p, name, "");
  if (value.empty()) xml.fail(where, std::string("<") + name + "> is missing");
  return value;
}

}  // namespace

void readP3dPlugin(const XMLElement* p, const std::string& where, const XmlValues& xml,
                   RobotSpec* spec) {
  P3dSpec s;
  s.name = attribute(p, "name");
  s.body = required(xml, p, "bodyName", where);
  s.topic = required(xml, p, "topicName", where);
  s.frame = xml.text(p, "frameName", s.frame);
  s.offset.position = vector3(xml, p, "xyzOffset", where);
  const Eigen::Vector3d rpy = vector3(xml, p, "rpyOffset", where);
  s.offset.orientation = Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX());
  s.gaussian_noise = xml.number(p, "gaussianNoise", 0, where);
  if (!(s.gaussian_noise >= 0) || !std::isfinite(s.gaussian_noise)) {
    xml.fail(where + " <gaussianNoise>", std::to_string(s.gaussian_noise) + " is not >= 0");
  }
  s.update_rate_hz = readRate(xml, p, "updateRate", 0, where);
  spec->p3ds.push_back(s);
}

void readForcePlugin(const XMLElement* p, const std::string& where, const XmlValues& xml,
                     RobotSpec* spec) {
  ForceSpec s;
  s.body = required(xml, p, "bodyName", where);
  s.topic = required(xml, p, "topicName", where);
  spec->forces.push_back(s);
}

}  // namespace bullet_sim
