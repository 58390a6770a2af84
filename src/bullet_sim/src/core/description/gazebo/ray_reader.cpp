#include "description/gazebo/ray_reader.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

void readHorizontal(const XMLElement* hor, const std::string& where, const XmlValues& xml,
                    RaySpec* r) {
  const std::string hw = where + " <horizontal>";
  const double samples = xml.number(hor, "samples", 1, hw);
  if (samples < 1 || samples != static_cast<int>(samples)) {
    xml.fail(hw + " <samples>", "'" + xml.text(hor, "samples", "") + "' is not a count >= 1");
  }
  r->samples = static_cast<int>(samples);
  r->min_angle_rad = xml.number(hor, "min_angle", 0, hw);
  r->max_angle_rad = xml.number(hor, "max_angle", 0, hw);
  if (!(r->min_angle_rad <= r->max_angle_rad)) {
    xml.fail(hw, "min_angle " + xml.text(hor, "min_angle", "") + " must not be above " +
                     "max_angle " + xml.text(hor, "max_angle", ""));
  }
}

void readRange(const XMLElement* range, const std::string& where, const XmlValues& xml,
               RaySpec* r) {
  const std::string rw = where + " <range>";
  r->range_min_m = xml.number(range, "min", r->range_min_m, rw);
  r->range_max_m = xml.number(range, "max", r->range_max_m, rw);
  r->range_resolution_m = xml.number(range, "resolution", 0, rw);
  if (!(r->range_min_m >= 0 && r->range_min_m < r->range_max_m)) {
    xml.fail(rw, "min " + xml.text(range, "min", "") + " must be >= 0 and below max " +
                     xml.text(range, "max", ""));
  }
}

}  // namespace

void readRaySensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  RaySpec r;
  r.name = e.name;
  r.link = e.link;
  r.pose_in_link = xml.pose(e.sensor, "pose", e.where);
  r.update_rate_hz = readRate(xml, e.sensor, "update_rate", r.update_rate_hz, e.where);
  const XMLElement* ray = e.sensor->FirstChildElement("ray");
  const XMLElement* scan = ray ? ray->FirstChildElement("scan") : nullptr;
  const XMLElement* hor = scan ? scan->FirstChildElement("horizontal") : nullptr;
  const XMLElement* range = ray ? ray->FirstChildElement("range") : nullptr;
  if (!hor || !range) xml.fail(e.where, "needs <ray><scan><horizontal> and <ray><range>");
  readHorizontal(hor, e.where, xml, &r);
  readRange(range, e.where, xml, &r);
  if (const XMLElement* noise = ray->FirstChildElement("noise")) {
    r.noise_mean_m = xml.number(noise, "mean", 0, e.where + " <noise>");
    r.noise_stddev_m = xml.number(noise, "stddev", 0, e.where + " <noise>");
  }
  r.topic = xml.text(e.plugin, "topicName", r.topic);
  r.frame_id = xml.text(e.plugin, "frameName", e.link);
  spec->rays.push_back(r);
}

}  // namespace bullet_sim
