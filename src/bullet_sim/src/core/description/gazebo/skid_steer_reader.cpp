#include "description/gazebo/skid_steer_reader.h"

#include <cmath>

#include "description/gazebo/gazebo_values.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

void readJoints(const XMLElement* p, const XmlValues& xml, DiffDriveSpec* d) {
  d->left_joint = xml.text(p, "leftFrontJoint", "left_front_joint");
  d->right_joint = xml.text(p, "rightFrontJoint", "right_front_joint");
  d->left_rear_joint = xml.text(p, "leftRearJoint", "left_rear_joint");
  d->right_rear_joint = xml.text(p, "rightRearJoint", "right_rear_joint");
}

void readTopicsAndFrames(const XMLElement* p, const std::string& where, const XmlValues& xml,
                         DiffDriveSpec* d) {
  d->command_topic = xml.text(p, "commandTopic", "cmd_vel");
  d->odometry_topic = xml.text(p, "odometryTopic", "odom");
  d->odometry_frame = xml.text(p, "odometryFrame", "odom");
  d->robot_base_frame = xml.text(p, "robotBaseFrame", "base_footprint");
  d->publish_odom_tf = xml.boolean(p, "broadcastTF", false, where);
}

void requirePositive(double value, const std::string& where, const char* name,
                     const XmlValues& xml) {
  if (!(value > 0) || !std::isfinite(value)) {
    xml.fail(where + " <" + name + ">", std::to_string(value) + " is not a number > 0");
  }
}

void readWheels(const XMLElement* p, const std::string& where, const XmlValues& xml,
                DiffDriveSpec* d) {
  d->wheel_separation_m = xml.number(p, "wheelSeparation", 0.4, where);
  d->wheel_diameter_m = xml.number(p, "wheelDiameter", 0.15, where);
  d->wheel_torque_nm = xml.number(p, "torque", 5.0, where);
  d->update_rate_hz = readRate(xml, p, "updateRate", 100.0, where);
  requirePositive(d->wheel_separation_m, where, "wheelSeparation", xml);
  requirePositive(d->wheel_diameter_m, where, "wheelDiameter", xml);
  requirePositive(d->wheel_torque_nm, where, "torque", xml);
}

Eigen::Vector3d readCovariance(const XMLElement* p, const std::string& where,
                               const XmlValues& xml) {
  const char* names[3] = {"covariance_x", "covariance_y", "covariance_yaw"};
  const double defaults[3] = {0.0001, 0.0001, 0.01};
  Eigen::Vector3d c;
  for (int i = 0; i < 3; ++i) {
    c[i] = xml.number(p, names[i], defaults[i], where);
    if (!(c[i] >= 0) || !std::isfinite(c[i])) {
      xml.fail(where + " <" + names[i] + ">", std::to_string(c[i]) + " is not a number >= 0");
    }
  }
  return c;
}

}  // namespace

void readSkidSteerDrivePlugin(const XMLElement* plugin, const std::string& where,
                              const XmlValues& xml, RobotSpec* spec) {
  if (spec->diff_drive) {
    xml.fail(where, "a second drive plugin (the first is " + spec->diff_drive->plugin + ")");
  }
  DiffDriveSpec d;
  d.plugin = "libgazebo_ros_skid_steer_drive.so";
  readJoints(plugin, xml, &d);
  readTopicsAndFrames(plugin, where, xml, &d);
  readWheels(plugin, where, xml, &d);
  d.wheel_acceleration = 0;
  d.odometry_source = OdomSource::World;
  d.odometry_covariance_xy_yaw = readCovariance(plugin, where, xml);
  spec->diff_drive = d;
}

}  // namespace bullet_sim
