#include "description/gazebo/imu_reader.h"

namespace bullet_sim {

void readImuSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  ImuSpec imu;
  imu.name = e.name;
  imu.link = e.link;
  imu.update_rate_hz = readRate(xml, e.sensor, "update_rate", 0, e.where);
  const std::string pw = e.where + " <plugin>";
  imu.topic = xml.text(e.plugin, "topicName", imu.topic);
  imu.frame_id = xml.text(e.plugin, "frameName", e.link);
  imu.update_rate_hz = readRate(xml, e.plugin, "updateRateHZ", imu.update_rate_hz, pw);
  imu.gaussian_noise = xml.number(e.plugin, "gaussianNoise", 0, pw);
  spec->imus.push_back(imu);
}

void readImuPlugin(const tinyxml2::XMLElement* p, const std::string& where,
                   const XmlValues& xml, RobotSpec* spec) {
  ImuSpec imu;
  imu.name = attribute(p, "name");
  imu.link = xml.text(p, "bodyName", "");
  if (imu.link.empty()) xml.fail(where, "<bodyName> is missing");
  imu.topic = xml.text(p, "topicName", imu.topic);
  imu.frame_id = xml.text(p, "frameName", imu.link);
  imu.update_rate_hz = readRate(xml, p, "updateRate", 0, where);
  imu.gaussian_noise = xml.number(p, "gaussianNoise", 0, where);
  spec->imus.push_back(imu);
}

}  // namespace bullet_sim
