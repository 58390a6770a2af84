#include "description/gazebo/depth_camera_reader.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "description/gazebo/camera_reader.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// The upper cutoff: the kinect plugin's <pointCloudCutoffMax>, none for the depth camera
/// plugin (which warns about the parameter).
double readCutoffMax(const XMLElement* plugin, const std::string& pw, const XmlValues& xml,
                     const DepthSpec& d, std::vector<std::string>* warnings) {
  if (d.plugin == kKinectPlugin) {
    return xml.number(plugin, "pointCloudCutoffMax", d.cutoff_max_m, pw);
  }
  if (plugin->FirstChildElement("pointCloudCutoffMax")) {
    warnings->push_back(pw + " <pointCloudCutoffMax>: not a parameter of " + d.plugin +
                        " (it has no upper cutoff): ignored");
  }
  return std::numeric_limits<double>::infinity();
}

void checkCutoffs(const XMLElement* plugin, const std::string& pw, const XmlValues& xml,
                  const DepthSpec& d) {
  if (!(d.cutoff_m >= 0 && std::isfinite(d.cutoff_m))) {
    xml.fail(pw + " <pointCloudCutoff>",
             "'" + xml.text(plugin, "pointCloudCutoff", "") + "' must be >= 0");
  }
  if (!(d.cutoff_max_m > d.cutoff_m)) {
    xml.fail(pw + " <pointCloudCutoffMax>", "'" + xml.text(plugin, "pointCloudCutoffMax", "") +
                                                "' must be above <pointCloudCutoff> " +
                                                std::to_string(d.cutoff_m));
  }
}

}  // namespace

void readDepthCameraSensor(const SensorElement& e, const XmlValues& xml, RobotSpec* spec) {
  checkCameraValues(e.sensor, e.where, xml);
  CameraSpec c = readCamera(e, xml, "ir/image_raw", "ir/camera_info");
  const XMLElement* plugin = e.plugin;
  DepthSpec d;
  d.plugin = attribute(plugin, "filename");
  const std::string pw = e.where + " <plugin filename=\"" + d.plugin + "\">";
  d.depth_image_topic = xml.text(plugin, "depthImageTopicName", d.depth_image_topic);
  d.depth_info_topic = xml.text(plugin, "depthImageCameraInfoTopicName", d.depth_info_topic);
  d.point_cloud_topic = xml.text(plugin, "pointCloudTopicName", d.point_cloud_topic);
  d.cutoff_m = xml.number(plugin, "pointCloudCutoff", d.cutoff_m, pw);
  d.cutoff_max_m = readCutoffMax(plugin, pw, xml, d, &spec->warnings);
  checkCutoffs(plugin, pw, xml, d);
  c.depth = d;
  spec->cameras.push_back(c);
}

}  // namespace bullet_sim
