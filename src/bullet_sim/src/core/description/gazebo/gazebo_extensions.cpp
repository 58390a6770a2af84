#include "description/gazebo/gazebo_extensions.h"
#include "description/gazebo/plugin_parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "bullet_sim/errors.h"
#include "description/gazebo/lens_reader.h"
#include "description/material/gazebo_materials.h"
#include "description/xml_values.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

constexpr const char* kKinectPlugin = "libgazebo_ros_openni_kinect.so";
constexpr const char* kDepthCameraPlugin = "libgazebo_ros_depth_camera.so";

std::string attr(const XMLElement* e, const char* name) {
  const char* v = e->Attribute(name);
  return v ? v : "";
}

/// Parses one <gazebo> block's sensors and plugins with shared context.
class ExtensionReader {
 public:
  ExtensionReader(const std::string& source, RobotSpec* spec) : xml_(source), spec_(spec) {}

  void readBlock(const XMLElement* gazebo) {
    const std::string link = attr(gazebo, "reference");
    if (!link.empty()) readSurface(gazebo, link);
    if (!link.empty()) readMaterial(gazebo, link);
    for (const XMLElement* s = gazebo->FirstChildElement("sensor"); s;
         s = s->NextSiblingElement("sensor")) {
      readSensor(s, link);
    }
    for (const XMLElement* p = gazebo->FirstChildElement("plugin"); p;
         p = p->NextSiblingElement("plugin")) {
      readModelPlugin(p);
    }
  }

  /// Warns about sensors without a ROS plugin, once every block is read: an
  /// IMU sensor whose link a model-level IMU plugin (libgazebo_ros_imu.so,
  /// bodyName) already publishes is fine, as the Burger's is.
  void finish() {
    for (const Pluginless& p : pluginless_) {
      const bool published_by_model_plugin =
          p.type == "imu" && std::any_of(spec_->imus.begin(), spec_->imus.end(),
                                         [&](const ImuSpec& imu) { return imu.link == p.link; });
      if (published_by_model_plugin) continue;
      spec_->warnings.push_back(p.type + " sensor '" + p.name + "' on link '" + p.link +
                                "' has no ROS plugin: as in Gazebo, no ROS topic carries it");
    }
  }

 private:
  void readSurface(const XMLElement* g, const std::string& link) {
    const std::string where = "<gazebo reference=\"" + link + "\">";
    if (!g->FirstChildElement("mu1") && !g->FirstChildElement("mu2") &&
        !g->FirstChildElement("kp") && !g->FirstChildElement("kd")) {
      return;
    }
    SurfaceParams s = spec_->surfaces[link];
    s.mu1 = xml_.number(g, "mu1", s.mu1, where);
    s.mu2 = xml_.number(g, "mu2", s.mu2, where);
    s.kp = xml_.number(g, "kp", s.kp, where);
    s.kd = xml_.number(g, "kd", s.kd, where);
    for (const auto& [name, mu] : {std::make_pair("mu1", s.mu1), std::make_pair("mu2", s.mu2)}) {
      if (!(mu >= 0)) {
        xml_.fail(where + " <" + name + ">",
                  "'" + xml_.text(g, name, "") + "' is not a friction coefficient >= 0");
      }
    }
    spec_->surfaces[link] = s;
  }

  /// <gazebo reference="link"><material>Gazebo/Red</material>: Gazebo draws every visual
  /// of the link in that material, whatever the URDF <material> says.
  void readMaterial(const XMLElement* g, const std::string& link) {
    if (!g->FirstChildElement("material")) return;
    const std::string name = xml_.text(g, "material", "");
    std::optional<Eigen::Vector4f> colour = gazeboMaterialColour(name);
    if (!colour) {
      spec_->warnings.push_back("<gazebo reference=\"" + link + "\"> <material>: '" + name +
                                "' is not one of Gazebo's stock materials: drawn grey");
      colour = unknownMaterialColour();
    }
    for (VisualSpec& v : spec_->visuals) {
      if (v.link == link) v.rgba = *colour;
    }
  }

  void readSensor(const XMLElement* s, const std::string& link) {
    const std::string type = attr(s, "type");
    const std::string name = attr(s, "name");
    const std::string where = "<gazebo reference=\"" + link + "\"> <sensor name=\"" + name + "\">";
    if (link.empty()) xml_.fail(where, "a sensor needs a <gazebo reference=\"link\">");
    const XMLElement* plugin = s->FirstChildElement("plugin");
    const std::string file = plugin ? attr(plugin, "filename") : "";
    // Only a plugin that this sensor uses is checked: a left-out one is warned about whole.
    const auto checkParameters = [&] {
      warnUnknownPluginParameters(plugin, file, where + " <plugin>", &spec_->warnings);
    };
    if (type == "ray" || type == "gpu_ray") {
      if (file != "libgazebo_ros_laser.so" && file != "libgazebo_ros_gpu_laser.so") {
        return noPlugin(type, name, link, file);
      }
      checkParameters();
      readRay(s, plugin, link, name, where);
    } else if (type == "imu") {
      if (file != "libgazebo_ros_imu_sensor.so") return noPlugin(type, name, link, file);
      checkParameters();
      ImuSpec imu;
      imu.name = name;
      imu.link = link;
      imu.update_rate_hz = rate(s, "update_rate", 0, where);
      const std::string pw = where + " <plugin>";
      imu.topic = xml_.text(plugin, "topicName", imu.topic);
      imu.frame_id = xml_.text(plugin, "frameName", link);
      imu.update_rate_hz = rate(plugin, "updateRateHZ", imu.update_rate_hz, pw);
      imu.gaussian_noise = xml_.number(plugin, "gaussianNoise", 0, pw);
      spec_->imus.push_back(imu);
    } else if (type == "camera") {
      if (file != "libgazebo_ros_camera.so") return noPlugin(type, name, link, file);
      checkParameters();
      checkCameraValues(s, where);
      spec_->cameras.push_back(
          readCamera(s, plugin, link, name, where, "image_raw", "camera_info"));
    } else if (type == "wideanglecamera") {
      if (file != "libgazebo_ros_camera.so") return noPlugin(type, name, link, file);
      checkParameters();
      checkCameraValues(s, where, true);
      CameraSpec c = readCamera(s, plugin, link, name, where, "image_raw", "camera_info");
      c.lens = readLens(s->FirstChildElement("camera"), c.horizontal_fov_rad, xml_,
                        where + " <camera>");
      spec_->cameras.push_back(c);
    } else if (type == "depth") {
      if (file != kKinectPlugin && file != kDepthCameraPlugin) {
        return noPlugin(type, name, link, file);
      }
      checkParameters();
      readDepthCamera(s, plugin, link, name, where);
    } else {
      spec_->warnings.push_back("sensor type '" + type + "' (sensor '" + name + "' on link '" +
                                link + "') is not supported: ignored");
    }
  }

  /// An update rate in Hz: 0 means every step, as in Gazebo; a negative one is an error.
  double rate(const XMLElement* parent, const char* name, double fallback,
              const std::string& where) const {
    const double hz = xml_.number(parent, name, fallback, where);
    if (!(hz >= 0 && std::isfinite(hz))) {
      xml_.fail(where + " <" + name + ">", "'" + xml_.text(parent, name, "") +
                                             "' is not a rate >= 0 Hz");
    }
    return hz;
  }

  void noPlugin(const std::string& type, const std::string& name, const std::string& link,
                const std::string& file) {
    if (file.empty()) {
      pluginless_.push_back({type, name, link});
    } else {
      spec_->warnings.push_back("plugin '" + file + "' in " + type + " sensor '" + name +
                                "' on link '" + link + "' is not supported: ignored");
    }
  }

  void readRay(const XMLElement* s, const XMLElement* plugin, const std::string& link,
               const std::string& name, const std::string& where) {
    RaySpec r;
    r.name = name;
    r.link = link;
    r.pose_in_link = xml_.pose(s, "pose", where);
    r.update_rate_hz = rate(s, "update_rate", r.update_rate_hz, where);
    const XMLElement* ray = s->FirstChildElement("ray");
    const XMLElement* scan = ray ? ray->FirstChildElement("scan") : nullptr;
    const XMLElement* hor = scan ? scan->FirstChildElement("horizontal") : nullptr;
    const XMLElement* range = ray ? ray->FirstChildElement("range") : nullptr;
    if (!hor || !range) xml_.fail(where, "needs <ray><scan><horizontal> and <ray><range>");
    const std::string hw = where + " <horizontal>";
    const double samples = xml_.number(hor, "samples", 1, hw);
    if (samples < 1 || samples != static_cast<int>(samples)) {
      xml_.fail(hw + " <samples>", "'" + xml_.text(hor, "samples", "") + "' is not a count >= 1");
    }
    r.samples = static_cast<int>(samples);
    r.min_angle_rad = xml_.number(hor, "min_angle", 0, hw);
    r.max_angle_rad = xml_.number(hor, "max_angle", 0, hw);
    if (!(r.min_angle_rad <= r.max_angle_rad)) {
      xml_.fail(hw, "min_angle " + xml_.text(hor, "min_angle", "") + " must not be above " +
                        "max_angle " + xml_.text(hor, "max_angle", ""));
    }
    const std::string rw = where + " <range>";
    r.range_min_m = xml_.number(range, "min", r.range_min_m, rw);
    r.range_max_m = xml_.number(range, "max", r.range_max_m, rw);
    r.range_resolution_m = xml_.number(range, "resolution", 0, rw);
    if (!(r.range_min_m >= 0 && r.range_min_m < r.range_max_m)) {
      xml_.fail(rw, "min " + xml_.text(range, "min", "") + " must be >= 0 and below max " +
                        xml_.text(range, "max", ""));
    }
    if (const XMLElement* noise = ray->FirstChildElement("noise")) {
      r.noise_mean_m = xml_.number(noise, "mean", 0, where + " <noise>");
      r.noise_stddev_m = xml_.number(noise, "stddev", 0, where + " <noise>");
    }
    r.topic = xml_.text(plugin, "topicName", r.topic);
    r.frame_id = xml_.text(plugin, "frameName", link);
    spec_->rays.push_back(r);
  }

  /// The camera part of a camera or depth sensor; the topics default to the plugin's.
  CameraSpec readCamera(const XMLElement* s, const XMLElement* plugin, const std::string& link,
                        const std::string& name, const std::string& where,
                        const std::string& image_topic, const std::string& info_topic) {
    CameraSpec c;
    c.name = name;
    c.link = link;
    c.pose_in_link = xml_.pose(s, "pose", where);
    c.update_rate_hz = rate(s, "update_rate", 0, where);
    const XMLElement* cam = s->FirstChildElement("camera");
    if (!cam) xml_.fail(where, "needs a <camera> element");
    const std::string cw = where + " <camera>";
    c.horizontal_fov_rad = xml_.number(cam, "horizontal_fov", c.horizontal_fov_rad, cw);
    if (const XMLElement* image = cam->FirstChildElement("image")) {
      c.width = static_cast<int>(xml_.number(image, "width", c.width, cw + " <image>"));
      c.height = static_cast<int>(xml_.number(image, "height", c.height, cw + " <image>"));
      c.format = xml_.text(image, "format", c.format);
    }
    if (const XMLElement* clip = cam->FirstChildElement("clip")) {
      c.clip_near_m = xml_.number(clip, "near", c.clip_near_m, cw + " <clip>");
      c.clip_far_m = xml_.number(clip, "far", c.clip_far_m, cw + " <clip>");
    }
    if (c.width < 1 || c.height < 1) xml_.fail(cw + " <image>", "width and height must be >= 1");
    const std::string pw = where + " <plugin>";
    c.camera_name = xml_.text(plugin, "cameraName", c.camera_name);
    c.image_topic = xml_.text(plugin, "imageTopicName", image_topic);
    c.info_topic = xml_.text(plugin, "cameraInfoTopicName", info_topic);
    c.frame_id = xml_.text(plugin, "frameName", link);
    const double plugin_rate = rate(plugin, "updateRate", 0, pw);
    if (plugin_rate > 0) c.update_rate_hz = plugin_rate;
    return c;
  }

  /// Gazebo's depth plugins publish the colour image as a camera does (under ir/ unless
  /// told otherwise), plus depth image, its camera_info and the point cloud.
  void readDepthCamera(const XMLElement* s, const XMLElement* plugin, const std::string& link,
                       const std::string& name, const std::string& where) {
    checkCameraValues(s, where);
    CameraSpec c = readCamera(s, plugin, link, name, where, "ir/image_raw", "ir/camera_info");
    DepthSpec d;
    d.plugin = attr(plugin, "filename");
    const std::string pw = where + " <plugin filename=\"" + d.plugin + "\">";
    d.depth_image_topic = xml_.text(plugin, "depthImageTopicName", d.depth_image_topic);
    d.depth_info_topic = xml_.text(plugin, "depthImageCameraInfoTopicName", d.depth_info_topic);
    d.point_cloud_topic = xml_.text(plugin, "pointCloudTopicName", d.point_cloud_topic);
    d.cutoff_m = xml_.number(plugin, "pointCloudCutoff", d.cutoff_m, pw);
    if (d.plugin == kKinectPlugin) {
      d.cutoff_max_m = xml_.number(plugin, "pointCloudCutoffMax", d.cutoff_max_m, pw);
    } else {
      d.cutoff_max_m = std::numeric_limits<double>::infinity();
      if (plugin->FirstChildElement("pointCloudCutoffMax")) {
        spec_->warnings.push_back(pw + " <pointCloudCutoffMax>: not a parameter of " +
                                  d.plugin + " (it has no upper cutoff): ignored");
      }
    }
    if (!(d.cutoff_m >= 0 && std::isfinite(d.cutoff_m))) {
      xml_.fail(pw + " <pointCloudCutoff>",
                "'" + xml_.text(plugin, "pointCloudCutoff", "") + "' must be >= 0");
    }
    if (!(d.cutoff_max_m > d.cutoff_m)) {
      xml_.fail(pw + " <pointCloudCutoffMax>", "'" + xml_.text(plugin, "pointCloudCutoffMax", "") +
                                                   "' must be above <pointCloudCutoff> " +
                                                   std::to_string(d.cutoff_m));
    }
    c.depth = d;
    spec_->cameras.push_back(c);
  }

  /// A camera's <camera> values that no renderer can use are load errors. A wide-angle
  /// camera's horizontal fov may reach 2 pi, a pinhole's stays below pi.
  void checkCameraValues(const XMLElement* s, const std::string& where, bool wide_angle = false) {
    const XMLElement* cam = s->FirstChildElement("camera");
    if (!cam) xml_.fail(where, "needs a <camera> element");
    const std::string cw = where + " <camera>";
    const double fov = xml_.number(cam, "horizontal_fov", 1.047, cw);
    if (!(fov > 0 && (wide_angle ? fov <= 2 * M_PI : fov < M_PI))) {
      xml_.fail(cw + " <horizontal_fov>", "'" + xml_.text(cam, "horizontal_fov", "") +
                                              (wide_angle ? "' must be in (0, 2 pi] radians"
                                                          : "' must be in (0, pi) radians"));
    }
    if (const XMLElement* image = cam->FirstChildElement("image")) {
      for (const char* dim : {"width", "height"}) {
        const double v = xml_.number(image, dim, 1, cw + " <image>");
        if (!(v >= 1 && v <= 16384 && v == std::floor(v))) {
          xml_.fail(cw + " <image> <" + dim + ">",
                    "'" + xml_.text(image, dim, "") + "' is not a pixel count in 1..16384");
        }
      }
      const std::string format = xml_.text(image, "format", "R8G8B8");
      if (format != "R8G8B8" && format != "B8G8R8" && format != "L8") {
        xml_.fail(cw + " <image> <format>", "'" + format + "' is not R8G8B8, B8G8R8 or L8");
      }
    }
    if (const XMLElement* clip = cam->FirstChildElement("clip")) {
      const double near = xml_.number(clip, "near", 0.1, cw + " <clip>");
      const double far = xml_.number(clip, "far", 100, cw + " <clip>");
      if (!(near > 0 && std::isfinite(near))) {
        xml_.fail(cw + " <clip> <near>", "'" + xml_.text(clip, "near", "") + "' must be > 0");
      }
      if (!(far > near && std::isfinite(far))) {
        xml_.fail(cw + " <clip> <far>", "'" + xml_.text(clip, "far", "") +
                                            "' must be finite and above <near>");
      }
    }
  }

  void readModelPlugin(const XMLElement* p) {
    const std::string file = attr(p, "filename");
    const std::string where = "<plugin name=\"" + attr(p, "name") + "\" filename=\"" + file + "\">";
    warnUnknownPluginParameters(p, file, where, &spec_->warnings);
    if (file == "libgazebo_ros_diff_drive.so") {
      readDiffDrive(p, where);
    } else if (file == "libgazebo_ros_imu.so") {
      ImuSpec imu;
      imu.name = attr(p, "name");
      imu.link = xml_.text(p, "bodyName", "");
      if (imu.link.empty()) xml_.fail(where, "<bodyName> is missing");
      imu.topic = xml_.text(p, "topicName", imu.topic);
      imu.frame_id = xml_.text(p, "frameName", imu.link);
      imu.update_rate_hz = rate(p, "updateRate", 0, where);
      imu.gaussian_noise = xml_.number(p, "gaussianNoise", 0, where);
      spec_->imus.push_back(imu);
    } else {
      spec_->warnings.push_back("plugin '" + file + "' (name '" + attr(p, "name") +
                                "') is not supported: ignored");
    }
  }

  void readDiffDrive(const XMLElement* p, const std::string& where) {
    if (spec_->diff_drive) xml_.fail(where, "a second libgazebo_ros_diff_drive.so plugin");
    DiffDriveSpec d;
    d.left_joint = xml_.text(p, "leftJoint", "");
    d.right_joint = xml_.text(p, "rightJoint", "");
    if (d.left_joint.empty() || d.right_joint.empty()) {
      xml_.fail(where, "<leftJoint> and <rightJoint> are required");
    }
    d.command_topic = xml_.text(p, "commandTopic", d.command_topic);
    d.odometry_topic = xml_.text(p, "odometryTopic", d.odometry_topic);
    d.odometry_frame = xml_.text(p, "odometryFrame", d.odometry_frame);
    d.robot_base_frame = xml_.text(p, "robotBaseFrame", d.robot_base_frame);
    d.wheel_separation_m = xml_.number(p, "wheelSeparation", d.wheel_separation_m, where);
    d.wheel_diameter_m = xml_.number(p, "wheelDiameter", d.wheel_diameter_m, where);
    d.wheel_torque_nm = xml_.number(p, "wheelTorque", d.wheel_torque_nm, where);
    d.wheel_acceleration = xml_.number(p, "wheelAcceleration", d.wheel_acceleration, where);
    d.update_rate_hz = rate(p, "updateRate", d.update_rate_hz, where);
    const std::string source = xml_.text(p, "odometrySource", "world");
    if (source == "world" || source == "1") {
      d.odometry_source = OdomSource::World;
    } else if (source == "encoder" || source == "0") {
      d.odometry_source = OdomSource::Encoder;
    } else {
      xml_.fail(where + " <odometrySource>", "'" + source + "' is not 'world' or 'encoder'");
    }
    d.publish_odom_tf = xml_.boolean(p, "publishOdomTF", d.publish_odom_tf, where);
    d.publish_wheel_tf = xml_.boolean(p, "publishWheelTF", d.publish_wheel_tf, where);
    d.publish_wheel_joint_state =
        xml_.boolean(p, "publishWheelJointState", d.publish_wheel_joint_state, where);
    if (d.wheel_separation_m <= 0) xml_.fail(where + " <wheelSeparation>", "must be > 0");
    if (d.wheel_diameter_m <= 0) xml_.fail(where + " <wheelDiameter>", "must be > 0");
    if (d.wheel_torque_nm <= 0) xml_.fail(where + " <wheelTorque>", "must be > 0");
    if (d.wheel_acceleration < 0) xml_.fail(where + " <wheelAcceleration>", "must be >= 0");
    spec_->diff_drive = d;
  }

  XmlValues xml_;
  RobotSpec* spec_;
  struct Pluginless {
    std::string type, name, link;
  };
  std::vector<Pluginless> pluginless_;
};

}  // namespace

void parseGazeboExtensions(const std::string& urdf_xml, const std::string& source,
                           RobotSpec* spec) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_xml.c_str()) != tinyxml2::XML_SUCCESS) {
    throw LoadError(source + ": malformed XML: " + doc.ErrorStr());
  }
  const XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot) throw LoadError(source + ": no <robot> element");
  ExtensionReader reader(source, spec);
  for (const XMLElement* g = robot->FirstChildElement("gazebo"); g;
       g = g->NextSiblingElement("gazebo")) {
    reader.readBlock(g);
  }
  reader.finish();
}

}  // namespace bullet_sim
