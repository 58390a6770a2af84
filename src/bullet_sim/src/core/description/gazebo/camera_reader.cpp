#include "description/gazebo/camera_reader.h"

#include <cmath>

#include "description/gazebo/lens_reader.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

void checkFov(const XMLElement* cam, const std::string& cw, const XmlValues& xml,
              bool wide_angle) {
  const double fov = xml.number(cam, "horizontal_fov", 1.047, cw);
  const bool in_range = fov > 0 && (wide_angle ? fov <= 2 * M_PI : fov < M_PI);
  if (!in_range) {
    xml.fail(cw + " <horizontal_fov>", "'" + xml.text(cam, "horizontal_fov", "") +
                                           (wide_angle ? "' must be in (0, 2 pi] radians"
                                                       : "' must be in (0, pi) radians"));
  }
}

void checkImage(const XMLElement* image, const std::string& cw, const XmlValues& xml) {
  for (const char* dim : {"width", "height"}) {
    const double v = xml.number(image, dim, 1, cw + " <image>");
    if (!(v >= 1 && v <= 16384 && v == std::floor(v))) {
      xml.fail(cw + " <image> <" + dim + ">",
               "'" + xml.text(image, dim, "") + "' is not a pixel count in 1..16384");
    }
  }
  const std::string format = xml.text(image, "format", "R8G8B8");
  if (format != "R8G8B8" && format != "B8G8R8" && format != "L8") {
    xml.fail(cw + " <image> <format>", "'" + format + "' is not R8G8B8, B8G8R8 or L8");
  }
}

void checkClip(const XMLElement* clip, const std::string& cw, const XmlValues& xml) {
  const double near = xml.number(clip, "near", 0.1, cw + " <clip>");
  const double far = xml.number(clip, "far", 100, cw + " <clip>");
  if (!(near > 0 && std::isfinite(near))) {
    xml.fail(cw + " <clip> <near>", "'" + xml.text(clip, "near", "") + "' must be > 0");
  }
  if (!(far > near && std::isfinite(far))) {
    xml.fail(cw + " <clip> <far>", "'" + xml.text(clip, "far", "") +
                                       "' must be finite and above <near>");
  }
}

/// The <camera> element's fov, image and clip into `c`.
void readCameraElement(const XMLElement* cam, const std::string& cw, const XmlValues& xml,
                       CameraSpec* c) {
  c->horizontal_fov_rad = xml.number(cam, "horizontal_fov", c->horizontal_fov_rad, cw);
  if (const XMLElement* image = cam->FirstChildElement("image")) {
    c->width = static_cast<int>(xml.number(image, "width", c->width, cw + " <image>"));
    c->height = static_cast<int>(xml.number(image, "height", c->height, cw + " <image>"));
    c->format = xml.text(image, "format", c->format);
  }
  if (const XMLElement* clip = cam->FirstChildElement("clip")) {
    c->clip_near_m = xml.number(clip, "near", c->clip_near_m, cw + " <clip>");
    c->clip_far_m = xml.number(clip, "far", c->clip_far_m, cw + " <clip>");
  }
  if (c->width < 1 || c->height < 1) xml.fail(cw + " <image>", "width and height must be >= 1");
}

/// The plugin's names, topics, frame and rate into `c`.
void readCameraPlugin(const SensorElement& e, const XmlValues& xml,
                      const std::string& image_topic, const std::string& info_topic,
                      CameraSpec* c) {
  const std::string pw = e.where + " <plugin>";
  c->camera_name = xml.text(e.plugin, "cameraName", c->camera_name);
  c->image_topic = xml.text(e.plugin, "imageTopicName", image_topic);
  c->info_topic = xml.text(e.plugin, "cameraInfoTopicName", info_topic);
  c->frame_id = xml.text(e.plugin, "frameName", e.link);
  const double plugin_rate = readRate(xml, e.plugin, "updateRate", 0, pw);
  if (plugin_rate > 0) c->update_rate_hz = plugin_rate;
}

}  // namespace

void checkCameraValues(const XMLElement* sensor, const std::string& where,
                       const XmlValues& xml, bool wide_angle) {
  const XMLElement* cam = sensor->FirstChildElement("camera");
  if (!cam) xml.fail(where, "needs a <camera> element");
  const std::string cw = where + " <camera>";
  checkFov(cam, cw, xml, wide_angle);
  if (const XMLElement* image = cam->FirstChildElement("image")) checkImage(image, cw, xml);
  if (const XMLElement* clip = cam->FirstChildElement("clip")) checkClip(clip, cw, xml);
}

CameraSpec readCamera(const SensorElement& e, const XmlValues& xml,
                      const std::string& image_topic, const std::string& info_topic) {
  CameraSpec c;
  c.name = e.name;
  c.link = e.link;
  c.pose_in_link = xml.pose(e.sensor, "pose", e.where);
  c.update_rate_hz = readRate(xml, e.sensor, "update_rate", 0, e.where);
  const XMLElement* cam = e.sensor->FirstChildElement("camera");
  if (!cam) xml.fail(e.where, "needs a <camera> element");
  readCameraElement(cam, e.where + " <camera>", xml, &c);
  readCameraPlugin(e, xml, image_topic, info_topic, &c);
  return c;
}

void readCameraSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  checkCameraValues(e.sensor, e.where, xml);
  spec->cameras.push_back(readCamera(e, xml, "image_raw", "camera_info"));
}

void readWideAngleCameraSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  checkCameraValues(e.sensor, e.where, xml, true);
  CameraSpec c = readCamera(e, xml, "image_raw", "camera_info");
  c.lens = readLens(e.sensor->FirstChildElement("camera"), c.horizontal_fov_rad, xml,
                    e.where + " <camera>");
  spec->cameras.push_back(c);
}

}  // namespace bullet_sim
