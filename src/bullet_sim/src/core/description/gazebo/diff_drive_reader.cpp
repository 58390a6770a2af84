#include "description/gazebo/diff_drive_reader.h"

#include "description/gazebo/gazebo_values.h"

namespace bullet_sim {
namespace {

using tinyxml2::XMLElement;

void readJointsAndTopics(const XMLElement* p, const std::string& where, const XmlValues& xml,
                         DiffDriveSpec* d) {
  d->left_joint = xml.text(p, "leftJoint", "");
  d->right_joint = xml.text(p, "rightJoint", "");
  if (d->left_joint.empty() || d->right_joint.empty()) {
    xml.fail(where, "<leftJoint> and <rightJoint> are required");
  }
  d->command_topic = xml.text(p, "commandTopic", d->command_topic);
  d->odometry_topic = xml.text(p, "odometryTopic", d->odometry_topic);
  d->odometry_frame = xml.text(p, "odometryFrame", d->odometry_frame);
  d->robot_base_frame = xml.text(p, "robotBaseFrame", d->robot_base_frame);
}

void readWheels(const XMLElement* p, const std::string& where, const XmlValues& xml,
                DiffDriveSpec* d) {
  d->wheel_separation_m = xml.number(p, "wheelSeparation", d->wheel_separation_m, where);
  d->wheel_diameter_m = xml.number(p, "wheelDiameter", d->wheel_diameter_m, where);
  d->wheel_torque_nm = xml.number(p, "wheelTorque", d->wheel_torque_nm, where);
  d->wheel_acceleration = xml.number(p, "wheelAcceleration", d->wheel_acceleration, where);
  d->update_rate_hz = readRate(xml, p, "updateRate", d->update_rate_hz, where);
}

OdomSource readOdometrySource(const XMLElement* p, const std::string& where,
                              const XmlValues& xml) {
  const std::string source = xml.text(p, "odometrySource", "world");
  if (source == "world" || source == "1") return OdomSource::World;
  if (source == "encoder" || source == "0") return OdomSource::Encoder;
  xml.fail(where + " <odometrySource>", "'" + source + "' is not 'world' or 'encoder'");
}

void readPublished(const XMLElement* p, const std::string& where, const XmlValues& xml,
                   DiffDriveSpec* d) {
  d->publish_odom_tf = xml.boolean(p, "publishOdomTF", d->publish_odom_tf, where);
  d->publish_wheel_tf = xml.boolean(p, "publishWheelTF", d->publish_wheel_tf, where);
  d->publish_wheel_joint_state =
      xml.boolean(p, "publishWheelJointState", d->publish_wheel_joint_state, where);
}

void checkWheels(const DiffDriveSpec& d, const std::string& where, const XmlValues& xml) {
  if (d.wheel_separation_m <= 0) xml.fail(where + " <wheelSeparation>", "must be > 0");
  if (d.wheel_diameter_m <= 0) xml.fail(where + " <wheelDiameter>", "must be > 0");
  if (d.wheel_torque_nm <= 0) xml.fail(where + " <wheelTorque>", "must be > 0");
  if (d.wheel_acceleration < 0) xml.fail(where + " <wheelAcceleration>", "must be >= 0");
}

}  // namespace

void readDiffDrivePlugin(const XMLElement* plugin, const std::string& where,
                         const XmlValues& xml, RobotSpec* spec) {
  if (spec->diff_drive) {
    xml.fail(where, "a second drive plugin (the first is " + spec->diff_drive->plugin + ")");
  }
  DiffDriveSpec d;
  readJointsAndTopics(plugin, where, xml, &d);
  readWheels(plugin, where, xml, &d);
  d.odometry_source = readOdometrySource(plugin, where, xml);
  readPublished(plugin, where, xml, &d);
  checkWheels(d, where, xml);
  spec->diff_drive = d;
}

}  // namespace bullet_sim
