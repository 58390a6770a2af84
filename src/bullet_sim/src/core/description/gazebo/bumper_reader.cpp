#include "description/gazebo/bumper_reader.h"

namespace bullet_sim {

void readBumperSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  BumperSpec b;
  b.name = e.name;
  b.link = e.link;
  b.update_rate_hz = readRate(xml, e.sensor, "update_rate", 0, e.where);
  const tinyxml2::XMLElement* contact = e.sensor->FirstChildElement("contact");
  const tinyxml2::XMLElement* collision = contact ? contact->FirstChildElement("collision") : nullptr;
  b.collision = collision ? xml.text(contact, "collision", "") : "";
  // SDF before 1.4 named it in an attribute: <collision name="..."/>.
  if (b.collision.empty() && collision) b.collision = attribute(collision, "name");
  if (b.collision.empty()) xml.fail(e.where + " <contact>", "<collision> is missing");
  b.topic = xml.text(e.plugin, "bumperTopicName", b.topic);
  b.frame_id = xml.text(e.plugin, "frameName", b.frame_id);
  spec->bumpers.push_back(b);
}

}  // namespace bullet_sim
