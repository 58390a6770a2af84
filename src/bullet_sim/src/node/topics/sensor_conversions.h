// Adapts the core's range, block-laser and bumper readings to ROS messages.
#pragma once

#include <bullet_sim/sensors/sensor_data.h>

#include <gazebo_msgs/ContactsState.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/Range.h>

namespace bullet_sim_node {

sensor_msgs::Range toMsg(const bullet_sim::RangeData& range);
sensor_msgs::PointCloud toMsg(const bullet_sim::BlockLaserCloudData& cloud);
/// Each state's `info` is a line naming the pair and the time, as Gazebo's plugin writes it.
gazebo_msgs::ContactsState toMsg(const bullet_sim::ContactsData& contacts);

}  // namespace bullet_sim_node
