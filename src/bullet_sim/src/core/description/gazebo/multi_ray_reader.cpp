#include "description/gazebo/multi_ray_reader.h"

#include <cmath>

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// <horizontal> or <vertical> of a <scan>: samples, resolution and the angle span.
void readScanAxis(const XMLElement* axis, const std::string& where, const XmlValues& xml,
                  int* samples, double* resolution, double* min_rad, double* max_rad) {
  const double n = xml.number(axis, "samples", 1, where);
  if (!(n >= 1 && n <= 1e6 && n == std::floor(n))) {
    xml.fail(where + " <samples>", "'" + xml.text(axis, "samples", "") + "' is not a count >= 1");
  }
  *samples = static_cast<int>(n);
  *resolution = xml.number(axis, "resolution", 1, where);
  if (!(*resolution > 0 && *resolution * n <= 1e6)) {
    xml.fail(where + " <resolution>",
             "'" + xml.text(axis, "resolution", "") + "' is not a resolution > 0");
  }
  *min_rad = xml.number(axis, "min_angle", 0, where);
  *max_rad = xml.number(axis, "max_angle", 0, where);
  if (!(std::isfinite(*min_rad) && std::isfinite(*max_rad) && *min_rad <= *max_rad)) {
    xml.fail(where, "min_angle " + xml.text(axis, "min_angle", "") + " must not be above " +
                        "max_angle " + xml.text(axis, "max_angle", ""));
  }
}

RayConeSpec readCone(const SensorElement& e, const XmlValues& xml) {
  RayConeSpec cone;
  const XMLElement* ray = e.sensor->FirstChildElement("ray");
  const XMLElement* scan = ray ? ray->FirstChildElement("scan") : nullptr;
  const XMLElement* hor = scan ? scan->FirstChildElement("horizontal") : nullptr;
  const XMLElement* range = ray ? ray->FirstChildElement("range") : nullptr;
  if (!hor || !range) xml.fail(e.where, "needs <ray><scan><horizontal> and <ray><range>");
  readScanAxis(hor, e.where + " <ray><scan><horizontal>", xml, &cone.samples, &cone.resolution,
               &cone.min_angle_rad, &cone.max_angle_rad);
  if (const XMLElement* vert = scan->FirstChildElement("vertical")) {
    readScanAxis(vert, e.where + " <ray><scan><vertical>", xml, &cone.vertical_samples,
                 &cone.vertical_resolution, &cone.vertical_min_angle_rad,
                 &cone.vertical_max_angle_rad);
  }
  const std::string rw = e.where + " <ray><range>";
  cone.range_min_m = xml.number(range, "min", 0, rw);
  cone.range_max_m = xml.number(range, "max", 0, rw);
  if (!(cone.range_min_m >= 0 && cone.range_min_m < cone.range_max_m &&
        std::isfinite(cone.range_max_m))) {
    xml.fail(rw, "min " + xml.text(range, "min", "") + " must be >= 0 and below max " +
                     xml.text(range, "max", ""));
  }
  return cone;
}

double readNoise(const SensorElement& e, const XmlValues& xml) {
  const double sd = xml.number(e.plugin, "gaussianNoise", 0, e.where + " <plugin>");
  if (!(sd >= 0 && std::isfinite(sd))) {
    xml.fail(e.where + " <plugin> <gaussianNoise>",
             "'" + xml.text(e.plugin, "gaussianNoise", "") + "' is not a standard deviation >= 0");
  }
  return sd;
}

}  // namespace

void readRangeSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  RangeSpec r;
  r.name = e.name;
  r.link = e.link;
  r.pose_in_link = xml.pose(e.sensor, "pose", e.where);
  r.rays = readCone(e, xml);
  const std::string pw = e.where + " <plugin>";
  r.topic = xml.text(e.plugin, "topicName", r.topic);
  r.frame_id = xml.text(e.plugin, "frameName", r.frame_id);
  r.infrared = xml.text(e.plugin, "radiation", "ultrasound") != "ultrasound";
  r.fov_rad = xml.number(e.plugin, "fov", r.fov_rad, pw);
  r.gaussian_noise = readNoise(e, xml);
  // The plugin publishes at the sensor's updates, at most one per 1 / <updateRate>.
  const double sensor_hz = readRate(xml, e.sensor, "update_rate", 0, e.where);
  const double plugin_hz = readRate(xml, e.plugin, "updateRate", 0, pw);
  r.update_rate_hz =
      plugin_hz > 0 && (sensor_hz == 0 || plugin_hz < sensor_hz) ? plugin_hz : sensor_hz;
  spec->ranges.push_back(r);
}

void readBlockLaserSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  BlockLaserSpec b;
  b.name = e.name;
  b.link = e.link;
  b.pose_in_link = xml.pose(e.sensor, "pose", e.where);
  b.rays = readCone(e, xml);
  b.topic = xml.text(e.plugin, "topicName", b.topic);
  b.frame_id = xml.text(e.plugin, "frameName", b.frame_id);
  b.gaussian_noise = readNoise(e, xml);
  b.update_rate_hz = readRate(xml, e.sensor, "update_rate", 0, e.where);
  spec->block_lasers.push_back(b);
}

}  // namespace bullet_sim
