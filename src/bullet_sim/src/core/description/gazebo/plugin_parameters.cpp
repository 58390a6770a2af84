#include "description/gazebo/plugin_parameters.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace bullet_sim {
namespace {

// Parameters of Gazebo ROS plugins (gazebo_plugins of ROS Noetic), by plugin file. Every
// plugin also takes the common ones below.
const std::vector<std::string> kCommon = {"robotNamespace", "alwaysOn", "updateRate",
                                          "rosDebugLevel"};
const std::vector<std::string> kCameraUtils = {
    "cameraName",     "imageTopicName", "cameraInfoTopicName", "frameName",
    "hackBaseline",   "distortionK1",   "distortionK2",        "distortionK3",
    "distortionT1",   "distortionT2",   "CxPrime",             "Cx",
    "Cy",             "focalLength",    "borderCrop",          "triggerTopicName",
    "autoDistortion", "imageTopic"};
const std::vector<std::string> kDepth = {
    "depthImageTopicName", "depthImageCameraInfoTopicName", "pointCloudTopicName",
    "pointCloudCutoff",    "pointCloudCutoffMax",           "useDepth16UC1Format",
    "reflectanceTopicName", "normalsTopicName",             "disparityTopicName"};
const std::vector<std::string> kImu = {"topicName",    "serviceName", "bodyName",
                                       "frameName",    "updateRateHZ", "gaussianNoise",
                                       "xyzOffset",    "xyzOffsets",   "rpyOffset",
                                       "rpyOffsets",   "initialOrientationAsReference"};

const std::map<std::string, std::vector<std::string>>& knownParameters() {
  static const std::map<std::string, std::vector<std::string>> known = [] {
    std::vector<std::string> camera = kCameraUtils;
    std::vector<std::string> depth = kCameraUtils;
    depth.insert(depth.end(), kDepth.begin(), kDepth.end());
    const std::vector<std::string> laser = {"topicName", "frameName", "hokuyoMinIntensity",
                                            "gaussianNoise"};
    const std::vector<std::string> diff_drive = {
        "leftJoint",        "rightJoint",     "wheelSeparation",  "wheelDiameter",
        "wheelTorque",      "wheelAcceleration", "commandTopic",  "odometryTopic",
        "odometryFrame",    "robotBaseFrame", "odometrySource",   "publishWheelTF",
        "publishOdomTF",    "publishWheelJointState", "publishTf", "legacyMode"};
    const std::vector<std::string> skid_steer = {
        "leftFrontJoint", "rightFrontJoint", "leftRearJoint",  "rightRearJoint",
        "wheelSeparation", "wheelDiameter",  "torque",         "commandTopic",
        "odometryTopic",  "odometryFrame",   "robotBaseFrame", "broadcastTF",
        "covariance_x",   "covariance_y",    "covariance_yaw"};
    return std::map<std::string, std::vector<std::string>>{
        {"libgazebo_ros_diff_drive.so", diff_drive},
        {"libgazebo_ros_skid_steer_drive.so", skid_steer},
        {"libgazebo_ros_p3d.so",
         {"bodyName", "topicName", "frameName", "xyzOffset", "rpyOffset", "gaussianNoise"}},
        {"libgazebo_ros_force.so", {"bodyName", "topicName"}},
        {"libgazebo_ros_planar_move.so",
         {"commandTopic", "odometryTopic", "odometryFrame", "robotBaseFrame", "odometryRate",
          "cmdTimeout"}},
        {"libgazebo_ros_joint_state_publisher.so", {"jointName"}},
        {"libgazebo_ros_f3d.so", {"bodyName", "topicName", "frameName"}},
        {"libgazebo_ros_ft_sensor.so", {"jointName", "topicName", "gaussianNoise"}},
        {"libgazebo_ros_laser.so", laser},
        {"libgazebo_ros_gpu_laser.so", laser},
        {"libgazebo_ros_camera.so", camera},
        {"libgazebo_ros_triggered_camera.so", camera},
        {"libgazebo_ros_multicamera.so", camera},
        {"libgazebo_ros_triggered_multicamera.so", camera},
        {"libgazebo_ros_openni_kinect.so", depth},
        {"libgazebo_ros_depth_camera.so", depth},
        {"libgazebo_ros_imu.so", kImu},
        {"libgazebo_ros_imu_sensor.so", kImu},
        {"libgazebo_ros_range.so", {"topicName", "frameName", "radiation", "fov", "gaussianNoise"}},
        {"libgazebo_ros_block_laser.so", laser},
        {"libgazebo_ros_bumper.so", {"bumperTopicName", "frameName"}}};
  }();
  return known;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearestName(const std::string& name, const std::vector<std::string>& known) {
  std::string best;
  size_t best_distance = name.size() / 3 + 1;
  for (const std::string& candidate : known) {
    const size_t d = editDistance(lower(name), lower(candidate));
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

void warnUnknownPluginParameters(const tinyxml2::XMLElement* plugin, const std::string& file,
                                 const std::string& where, std::vector<std::string>* warnings) {
  const auto entry = knownParameters().find(file);
  if (!plugin || entry == knownParameters().end()) return;
  std::vector<std::string> known = entry->second;
  known.insert(known.end(), kCommon.begin(), kCommon.end());
  for (const tinyxml2::XMLElement* e = plugin->FirstChildElement(); e;
       e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    const std::string nearest = nearestName(name, known);
    warnings->push_back(where + " <" + name + ">: " + file + " has no such parameter" +
                        (nearest.empty() ? "" : " (did you mean <" + nearest + ">?)") +
                        ": ignored");
  }
}

}  // namespace bullet_sim
