#include "description/gazebo/camera_reader.h"

#include <cmath>
#include <cstdio>

#include "description/gazebo/lens_reader.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

const char* const kFormats = "R8G8B8, B8G8R8, L8, R16G16B16 or L16 (or RGB_INT8, BGR_INT8, "
                             "L_INT8, RGB_INT16, L_INT16)";

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
  if (canonicalFormat(format).empty()) {
    xml.fail(cw + " <image> <format>", "'" + format + "' is not " + kFormats);
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

/// <noise> (gaussian only: Gazebo's cameras take no other type) and <distortion>.
void readNoiseAndDistortion(const XMLElement* cam, const std::string& cw, const XmlValues& xml,
                            CameraSpec* c) {
  if (const XMLElement* noise = cam->FirstChildElement("noise")) {
    const std::string nw = cw + " <noise>";
    const std::string type = xml.text(noise, "type", "none");
    if (type == "gaussian") {
      ImageNoiseSpec n;
      n.mean = xml.number(noise, "mean", 0, nw);
      n.stddev = xml.number(noise, "stddev", 0, nw);
      if (!(n.stddev >= 0 && std::isfinite(n.stddev) && std::isfinite(n.mean))) {
        xml.fail(nw + " <stddev>", "'" + xml.text(noise, "stddev", "") + "' must be >= 0");
      }
      c->noise = n;
    } else if (type != "none") {
      xml.fail(nw + " <type>", "'" + type + "' is not gaussian or none");
    }
  }
  if (const XMLElement* dist = cam->FirstChildElement("distortion")) {
    const std::string dw = cw + " <distortion>";
    DistortionSpec d;
    d.k1 = xml.number(dist, "k1", 0, dw);
    d.k2 = xml.number(dist, "k2", 0, dw);
    d.k3 = xml.number(dist, "k3", 0, dw);
    d.p1 = xml.number(dist, "p1", 0, dw);
    d.p2 = xml.number(dist, "p2", 0, dw);
    const std::string center = xml.text(dist, "center", "0.5 0.5");
    double x = 0, y = 0;
    char rest = 0;
    if (std::sscanf(center.c_str(), "%lf %lf %c", &x, &y, &rest) != 2 || !std::isfinite(x) ||
        !std::isfinite(y)) {
      xml.fail(dw + " <center>", "'" + center + "' is not two numbers");
    }
    d.center_x = x;
    d.center_y = y;
    for (double k : {d.k1, d.k2, d.k3, d.p1, d.p2}) {
      if (!std::isfinite(k)) xml.fail(dw, "coefficients must be finite");
    }
    c->distortion = d;
  }
}

/// The <camera> element's fov, image and clip into `c`.
void readCameraElement(const XMLElement* cam, const std::string& cw, const XmlValues& xml,
                       CameraSpec* c) {
  c->horizontal_fov_rad = xml.number(cam, "horizontal_fov", c->horizontal_fov_rad, cw);
  if (const XMLElement* image = cam->FirstChildElement("image")) {
    c->width = static_cast<int>(xml.number(image, "width", c->width, cw + " <image>"));
    c->height = static_cast<int>(xml.number(image, "height", c->height, cw + " <image>"));
    c->format = canonicalFormat(xml.text(image, "format", c->format));
  }
  if (const XMLElement* clip = cam->FirstChildElement("clip")) {
    c->clip_near_m = xml.number(clip, "near", c->clip_near_m, cw + " <clip>");
    c->clip_far_m = xml.number(clip, "far", c->clip_far_m, cw + " <clip>");
  }
  if (c->width < 1 || c->height < 1) xml.fail(cw + " <image>", "width and height must be >= 1");
  readNoiseAndDistortion(cam, cw, xml, c);
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
  c->hack_baseline_m = xml.number(e.plugin, "hackBaseline", 0, pw);
  const bool auto_distortion = xml.boolean(e.plugin, "autoDistortion", false, pw);
  if (auto_distortion && c->distortion) {
    const DistortionSpec& d = *c->distortion;
    c->info_distortion = {d.k1, d.k2, d.p1, d.p2, d.k3};
  } else if (!auto_distortion) {
    const char* names[5] = {"distortionK1", "distortionK2", "distortionT1", "distortionT2",
                            "distortionK3"};
    for (int i = 0; i < 5; ++i) c->info_distortion[i] = xml.number(e.plugin, names[i], 0, pw);
  }
  const std::string file = attribute(e.plugin, "filename");
  if (file == kTriggeredCameraPlugin || file == kTriggeredMultiCameraPlugin) {
    c->trigger_topic = xml.text(e.plugin, "triggerTopicName", "image_trigger");
  }
}

/// One <camera> of a multicamera sensor as a CameraSpec: its own pose after the sensor's.
CameraSpec readMultiCameraMember(const SensorElement& e, const XMLElement* cam,
                                 const std::string& suffix, double baseline, const XmlValues& xml) {
  CameraSpec c;
  const std::string cam_name = attribute(cam, "name");
  const std::string cw = e.where + " <camera name=\"" + cam_name + "\">";
  c.name = e.name + "::" + cam_name;
  c.link = e.link;
  const Pose3 sensor = xml.pose(e.sensor, "pose", e.where);
  const Pose3 own = xml.pose(cam, "pose", cw);
  c.pose_in_link.position = sensor.position + sensor.orientation * own.position;
  c.pose_in_link.orientation = sensor.orientation * own.orientation;
  c.update_rate_hz = readRate(xml, e.sensor, "update_rate", 0, e.where);
  readCameraElement(cam, cw, xml, &c);
  readCameraPlugin(e, xml, "image_raw", "camera_info", &c);
  c.camera_name += suffix;
  c.hack_baseline_m = baseline;
  return c;
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

std::string canonicalFormat(const std::string& format) {
  if (format == "R8G8B8" || format == "RGB_INT8") return "R8G8B8";
  if (format == "B8G8R8" || format == "BGR_INT8") return "B8G8R8";
  if (format == "L8" || format == "L_INT8") return "L8";
  if (format == "R16G16B16" || format == "RGB_INT16") return "R16G16B16";
  if (format == "L16" || format == "L_INT16") return "L16";
  return "";
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

void readMultiCameraSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  const double baseline = xml.number(e.plugin, "hackBaseline", 0, e.where + " <plugin>");
  bool any = false;
  for (const XMLElement* cam = e.sensor->FirstChildElement("camera"); cam;
       cam = cam->NextSiblingElement("camera")) {
    any = true;
    const std::string name = attribute(cam, "name");
    const std::string cw = e.where + " <camera name=\"" + name + "\">";
    // As Gazebo's plugin: a camera named *left* publishes under <cameraName>/left with no
    // baseline, one named *right* under <cameraName>/right with <hackBaseline>; others none.
    const bool left = name.find("left") != std::string::npos;
    const bool right = !left && name.find("right") != std::string::npos;
    if (!left && !right) {
      spec->warnings.push_back(cw + ": its name holds neither 'left' nor 'right': as in "
                               "Gazebo's multicamera plugin, nothing publishes it");
      continue;
    }
    checkFov(cam, cw, xml, false);
    if (const XMLElement* image = cam->FirstChildElement("image")) checkImage(image, cw, xml);
    if (const XMLElement* clip = cam->FirstChildElement("clip")) checkClip(clip, cw, xml);
    spec->cameras.push_back(
        readMultiCameraMember(e, cam, left ? "/left" : "/right", left ? 0.0 : baseline, xml));
  }
  if (!any) xml.fail(e.where, "a multicamera needs a <camera> element");
}

void readWideAngleCameraSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  checkCameraValues(e.sensor, e.where, xml, true);
  CameraSpec c = readCamera(e, xml, "image_raw", "camera_info");
  c.lens = readLens(e.sensor->FirstChildElement("camera"), c.horizontal_fov_rad, xml,
                    e.where + " <camera>");
  spec->cameras.push_back(c);
}

}  // namespace bullet_sim
