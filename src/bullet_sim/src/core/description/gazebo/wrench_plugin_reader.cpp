#include "description/gazebo/wrench_plugin_reader.h"

#include <cmath>

#include "description/gazebo/gazebo_values.h"

namespace bullet_sim {
namespace {

std::string requiredText(const XmlValues& xml, const tinyxml2::XMLElement* p, const char* name,
                         const std::string& where) {
  const std::string value = xml.text(p, name, "");
  if (value.empty()) xml.fail(where, std::string("<") + name + "> is missing");
  return value;
}

}  // namespace

void readF3dPlugin(const tinyxml2::XMLElement* p, const std::string& where,
                   const XmlValues& xml, RobotSpec* spec) {
  F3dSpec s;
  s.body = requiredText(xml, p, "bodyName", where);
  s.topic = requiredText(xml, p, "topicName", where);
  s.frame = xml.text(p, "frameName", s.frame);
  spec->f3ds.push_back(s);
}

void readFtSensorPlugin(const tinyxml2::XMLElement* p, const std::string& where,
                        const XmlValues& xml, RobotSpec* spec) {
  FtSensorSpec s;
  s.name = attribute(p, "name");
  s.joint = requiredText(xml, p, "jointName", where);
  s.topic = requiredText(xml, p, "topicName", where);
  s.gaussian_noise = xml.number(p, "gaussianNoise", 0, where);
  if (!(s.gaussian_noise >= 0) || !std::isfinite(s.gaussian_noise)) {
    xml.fail(where + " <gaussianNoise>", std::to_string(s.gaussian_noise) + " is not >= 0");
  }
  s.update_rate_hz = readRate(xml, p, "updateRate", 0, where);
  spec->ft_sensors.push_back(s);
}

}  // namespace bullet_sim
