#include "topics/sensor_conversions.h"

#include "topics/conversions.h"

#include <sstream>

namespace bullet_sim_node {
namespace {

geometry_msgs::Wrench wrench(const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  geometry_msgs::Wrench out;
  out.force = toMsg(force);
  out.torque = toMsg(torque);
  return out;
}

}  // namespace

sensor_msgs::Range toMsg(const bullet_sim::RangeData& range) {
  sensor_msgs::Range msg;
  msg.header = toHeader(range.time_s, range.frame_id);
  msg.radiation_type = range.infrared ? sensor_msgs::Range::INFRARED : sensor_msgs::Range::ULTRASOUND;
  msg.field_of_view = range.field_of_view;
  msg.min_range = range.min_range;
  msg.max_range = range.max_range;
  msg.range = range.range;
  return msg;
}

sensor_msgs::PointCloud toMsg(const bullet_sim::BlockLaserCloudData& cloud) {
  sensor_msgs::PointCloud msg;
  msg.header = toHeader(cloud.time_s, cloud.frame_id);
  msg.points.resize(cloud.points.size());
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    msg.points[i].x = cloud.points[i].x();
    msg.points[i].y = cloud.points[i].y();
    msg.points[i].z = cloud.points[i].z();
  }
  msg.channels.resize(1);
  msg.channels[0].values = cloud.intensities;
  return msg;
}

gazebo_msgs::ContactsState toMsg(const bullet_sim::ContactsData& contacts) {
  gazebo_msgs::ContactsState msg;
  msg.header = toHeader(contacts.time_s, contacts.frame_id);
  for (size_t i = 0; i < contacts.states.size(); ++i) {
    const bullet_sim::ContactStateData& s = contacts.states[i];
    gazebo_msgs::ContactState state;
    state.collision1_name = s.collision1_name;
    state.collision2_name = s.collision2_name;
    std::ostringstream info;
    info << "Debug:  i:(" << i << "/" << contacts.states.size()
         << ")     my geom:" << s.collision1_name << "   other geom:" << s.collision2_name
         << "         time:" << msg.header.stamp << "\n";
    state.info = info.str();
    for (size_t j = 0; j < s.forces.size(); ++j) {
      state.wrenches.push_back(wrench(s.forces[j], s.torques[j]));
      state.contact_positions.push_back(toMsg(s.positions[j]));
      state.contact_normals.push_back(toMsg(s.normals[j]));
      state.depths.push_back(s.depths[j]);
    }
    state.total_wrench = wrench(s.total_force, s.total_torque);
    msg.states.push_back(state);
  }
  return msg;
}

}  // namespace bullet_sim_node
