#include "description/gazebo/gazebo_extensions.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "bullet_sim/errors.h"
#include "description/gazebo/body_plugin_reader.h"
#include "description/gazebo/bumper_reader.h"
#include "description/gazebo/camera_reader.h"
#include "description/gazebo/depth_camera_reader.h"
#include "description/gazebo/diff_drive_reader.h"
#include "description/gazebo/gazebo_values.h"
#include "description/gazebo/imu_reader.h"
#include "description/gazebo/joint_state_publisher_reader.h"
#include "description/gazebo/link_extensions.h"
#include "description/gazebo/multi_ray_reader.h"
#include "description/gazebo/planar_move_reader.h"
#include "description/gazebo/plugin_parameters.h"
#include "description/gazebo/ray_reader.h"
#include "description/gazebo/skid_steer_reader.h"
#include "description/gazebo/wrench_plugin_reader.h"
#include "description/xml_values.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

/// A sensor type, the ROS plugin files that publish it, and the reader of the two.
struct SensorFamily {
  const char* type;
  std::vector<std::string> plugin_files;
  void (*read)(const SensorElement&, const XmlValues&, RobotSpec*);
};

const std::vector<SensorFamily>& sensorFamilies() {
  static const std::vector<std::string> lasers = {"libgazebo_ros_laser.so",
                                                  "libgazebo_ros_gpu_laser.so"};
  static const std::vector<SensorFamily> families = {
      {"ray", lasers, readRaySensor},
      {"ray", {"libgazebo_ros_range.so"}, readRangeSensor},
      {"ray", {"libgazebo_ros_block_laser.so"}, readBlockLaserSensor},
      {"gpu_ray", lasers, readRaySensor},
      {"imu", {"libgazebo_ros_imu_sensor.so"}, readImuSensor},
      {"camera", {"libgazebo_ros_camera.so", kTriggeredCameraPlugin}, readCameraSensor},
      {"multicamera",
       {"libgazebo_ros_multicamera.so", kTriggeredMultiCameraPlugin},
       readMultiCameraSensor},
      {"wideanglecamera", {"libgazebo_ros_camera.so"}, readWideAngleCameraSensor},
      {"depth", {kKinectPlugin, kDepthCameraPlugin}, readDepthCameraSensor},
      {"contact", {"libgazebo_ros_bumper.so"}, readBumperSensor}};
  return families;
}

/// Whether the simulator supports sensors of `type` at all.
bool knownSensorType(const std::string& type) {
  for (const SensorFamily& f : sensorFamilies()) {
    if (type == f.type) return true;
  }
  return false;
}

/// The family of `type` whose plugins include `file`, or null.
const SensorFamily* sensorFamily(const std::string& type, const std::string& file) {
  for (const SensorFamily& f : sensorFamilies()) {
    if (type != f.type) continue;
    if (std::find(f.plugin_files.begin(), f.plugin_files.end(), file) != f.plugin_files.end()) {
      return &f;
    }
  }
  return nullptr;
}

/// The reader of a model-level <plugin> file, or null for one the simulator does not support.
using ModelPluginReader = void (*)(const XMLElement*, const std::string&, const XmlValues&,
                                   RobotSpec*);
ModelPluginReader modelPluginReader(const std::string& file) {
  if (file == "libgazebo_ros_diff_drive.so") return readDiffDrivePlugin;
  if (file == "libgazebo_ros_imu.so") return readImuPlugin;
  if (file == "libgazebo_ros_skid_steer_drive.so") return readSkidSteerDrivePlugin;
  if (file == "libgazebo_ros_p3d.so") return readP3dPlugin;
  if (file == "libgazebo_ros_force.so") return readForcePlugin;
  if (file == "libgazebo_ros_planar_move.so") return readPlanarMovePlugin;
  if (file == "libgazebo_ros_joint_state_publisher.so") return readJointStatePublisherPlugin;
  if (file == "libgazebo_ros_f3d.so") return readF3dPlugin;
  if (file == "libgazebo_ros_ft_sensor.so") return readFtSensorPlugin;
  return nullptr;
}

/// Parses the <gazebo> blocks' surfaces, materials, sensors and plugins, handing each
/// sensor and plugin to the reader of its family.
class ExtensionReader {
 public:
  ExtensionReader(const std::string& source, RobotSpec* spec) : xml_(source), spec_(spec) {}

  void readBlock(const XMLElement* gazebo) {
    const std::string link = attribute(gazebo, "reference");
    if (!link.empty()) readLinkSurface(gazebo, link, xml_, spec_);
    if (!link.empty()) readLinkMaterial(gazebo, link, xml_, spec_);
    for (const XMLElement* s = gazebo->FirstChildElement("sensor"); s;
         s = s->NextSiblingElement("sensor")) {
      const std::string where =
          "<gazebo reference=\"" + link + "\"> <sensor name=\"" + attribute(s, "name") + "\">";
      if (link.empty()) xml_.fail(where, "a sensor needs a <gazebo reference=\"link\">");
      readSensor(s, link, where);
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

 /// An SDF <sensor> of `link` (its <pose> in the link frame), named by `where`.
  void readSdfSensor(const XMLElement* s, const std::string& link, const std::string& where) {
    readSensor(s, link, where);
  }
  /// An SDF model's <plugin>, `prefix` naming the model.
  void readSdfPlugin(const XMLElement* p, const std::string& prefix) {
    readModelPlugin(p, prefix);
  }

 private:
  void readSensor(const XMLElement* s, const std::string& link, const std::string& where) {
    const std::string type = attribute(s, "type");
    const std::string name = attribute(s, "name");
    const XMLElement* plugin = s->FirstChildElement("plugin");
    const std::string file = plugin ? attribute(plugin, "filename") : "";
    if (!knownSensorType(type)) {
      spec_->warnings.push_back("sensor type '" + type + "' (sensor '" + name + "' on link '" +
                                link + "') is not supported: ignored");
      return;
    }
    const SensorFamily* family = sensorFamily(type, file);
    if (!family) return noPlugin(type, name, link, file);
    // Only a plugin that this sensor uses is checked: a left-out one is warned about whole.
    warnUnknownPluginParameters(plugin, file, where + " <plugin>", &spec_->warnings);
    family->read({s, plugin, link, name, where}, xml_, spec_);
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

  void readModelPlugin(const XMLElement* p, const std::string& prefix = "") {
    const std::string file = attribute(p, "filename");
    const std::string where =
        prefix + "<plugin name=\"" + attribute(p, "name") + "\" filename=\"" + file + "\">";
    warnUnknownPluginParameters(p, file, where, &spec_->warnings);
    if (const ModelPluginReader read = modelPluginReader(file)) {
      read(p, where, xml_, spec_);
    } else {
      spec_->warnings.push_back("plugin '" + file + "' (name '" + attribute(p, "name") +
                                "') is not supported: ignored");
    }
  }

  XmlValues xml_;
  RobotSpec* spec_;
  struct Pluginless {
    std::string type, name, link;
  };
  std::vector<Pluginless> pluginless_;
};

/// `xml` parsed, or a LoadError naming `where`.
std::unique_ptr<tinyxml2::XMLDocument> parseElement(const std::string& xml,
                                                    const std::string& source,
                                                    const std::string& where) {
  auto doc = std::make_unique<tinyxml2::XMLDocument>();
  if (doc->Parse(xml.c_str()) != tinyxml2::XML_SUCCESS || !doc->RootElement()) {
    throw LoadError(source + ": " + where + ": malformed XML: " + doc->ErrorStr());
  }
  return doc;
}

/// Writes `pose` as the element's <pose> ("x y z roll pitch yaw"), replacing any.
void setPose(tinyxml2::XMLElement* e, const Pose3& pose) {
  if (XMLElement* old = e->FirstChildElement("pose")) e->DeleteChild(old);
  const Eigen::Matrix3d R = pose.orientation.normalized().toRotationMatrix();
  // roll-pitch-yaw of R = Rz(yaw) Ry(pitch) Rx(roll), as SDF reads a pose; at pitch +-pi/2
  // only yaw - roll (or yaw + roll) is defined: roll 0 carries it all in yaw.
  const double pitch = std::asin(std::max(-1.0, std::min(1.0, -R(2, 0))));
  const bool gimbal_lock = std::abs(R(2, 0)) > 1 - 1e-12;
  const double roll = gimbal_lock ? 0.0 : std::atan2(R(2, 1), R(2, 2));
  const double yaw = gimbal_lock ? std::atan2(-R(0, 1), R(1, 1)) : std::atan2(R(1, 0), R(0, 0));
  std::ostringstream text;
  text.precision(17);
  text << pose.position.x() << ' ' << pose.position.y() << ' ' << pose.position.z() << ' '
       << roll << ' ' << pitch << ' ' << yaw;
  XMLElement* p = e->GetDocument()->NewElement("pose");
  p->SetText(text.str().c_str());
  e->InsertFirstChild(p);
}

}  // namespace

void readSdfModelExtensions(const std::vector<SdfSensorText>& sensors,
                            const std::vector<SdfPluginText>& plugins,
                            const std::string& source, RobotSpec* spec) {
  ExtensionReader reader(source, spec);
  for (const SdfSensorText& s : sensors) {
    const auto doc = parseElement(s.xml, source, s.where);
    XMLElement* sensor = doc->RootElement();
    setPose(sensor, s.pose_in_link);
    reader.readSdfSensor(sensor, s.link, s.where);
  }
  for (const SdfPluginText& p : plugins) {
    const auto doc = parseElement(p.xml, source, p.where);
    reader.readSdfPlugin(doc->RootElement(), p.where);
  }
  reader.finish();
}

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
