// The ROS side of one simulated robot: its sensor publishers and its command subscriber.
#pragma once

#include <bullet_sim/simulation.h>

#include "topics/counted_publisher.h"
#include "topics/publish_queue.h"

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Wrench.h>
#include <ros/node_handle.h>

#include <string>
#include <vector>

namespace bullet_sim_node {

/// Publishes a robot's sensors (scan, imu, odom + tf, joint_states, range, block laser
/// points, bumper contacts, wrenches) as they fall due and
/// feeds its diff-drive commands to the simulation. Topic names come from the robot's
/// Gazebo tags, resolved in `robot_nh` (the robot's namespace); frame ids (odom, base,
/// scan, imu) are put under `tf_prefix` as Gazebo's plugins do. A sensor topic nobody
/// subscribes to is not read from the simulation at all; the odom tf is always sent. Messages
/// leave through `queue`, in the order they are made.
class RobotIo {
 public:
  /// `sim` and `queue` must outlive this object. Without `joint_states` the robot's joint
  /// states are not published (a world's own models: Gazebo publishes theirs only through
  /// a plugin). A robot with libgazebo_ros_joint_state_publisher.so plugins publishes
  /// theirs instead, with or without `joint_states`.
  RobotIo(bullet_sim::Simulation& sim, PublishQueue& queue, const std::string& robot,
          const ros::NodeHandle& robot_nh, const std::string& tf_prefix,
          bool joint_states = true);
  /// Whether a robot of `spec` has sensors or plugins that RobotIo publishes or subscribes
  /// besides its joint states.
  static bool hasTopics(const bullet_sim::RobotSpec& spec);
  RobotIo(const RobotIo&) = delete;
  RobotIo& operator=(const RobotIo&) = delete;

  /// Publishes the reading of one due sensor of this robot (not a ray: see below), if it
  /// is wanted.
  void publish(const bullet_sim::DueSensor& due);
  /// Whether the scan of ray sensor `index` is wanted; the caller reads the scans it wants
  /// (Simulation::readRays, several robots' at once) and publishes them here.
  bool wantsScan(size_t index) const;
  void publishScan(size_t index, const bullet_sim::LaserScanData& scan);

 private:
  void onCmdVel(const geometry_msgs::Twist::ConstPtr& command);
  /// A libgazebo_ros_force.so plugin's wrench message (plugin `index` of RobotSpec::forces).
  void onWrench(size_t index, const geometry_msgs::Wrench::ConstPtr& wrench);
  void publishOdometry();
  // gazebo_plugins' planar move and joint state publisher (robot_io_motion_plugins.cpp).
  void advertiseMotionPlugins(ros::NodeHandle& nh, const bullet_sim::RobotSpec& spec);
  /// The planar move's odometry and tf, or a joint state publisher's joints.
  void publishMotionPlugin(const bullet_sim::DueSensor& due);
  void onPlanarMoveCommand(const geometry_msgs::Twist::ConstPtr& command);
  /// An f3d's or ft_sensor's wrench, if someone subscribes.
  void publishWrench(const bullet_sim::DueSensor& due);
  /// A range sensor's, block laser's or bumper's reading, if someone subscribes.
  void publishRangeOrContacts(const bullet_sim::DueSensor& due);

  bullet_sim::Simulation& sim_;
  PublishQueue& queue_;
  const std::string robot_;
  const std::string tf_prefix_;
  std::vector<CountedPublisher> scan_pubs_;  ///< one per RaySpec, same index
  std::vector<CountedPublisher> imu_pubs_;   ///< one per ImuSpec, same index
  std::vector<CountedPublisher> range_pubs_;  ///< one per RangeSpec, same index
  std::vector<CountedPublisher> block_laser_pubs_;  ///< one per BlockLaserSpec, same index
  std::vector<CountedPublisher> bumper_pubs_;  ///< one per BumperSpec, same index
  CountedPublisher odom_pub_;
  std::vector<CountedPublisher> ground_truth_pubs_;  ///< one per P3dSpec, same index
  std::vector<ros::Subscriber> wrench_subs_;         ///< one per ForceSpec, same index
  std::vector<CountedPublisher> f3d_pubs_;  ///< one per F3dSpec, same index
  std::vector<CountedPublisher> ft_pubs_;   ///< one per FtSensorSpec, same index
  CountedPublisher joint_state_pub_;
  CountedPublisher planar_odom_pub_;  ///< libgazebo_ros_planar_move.so's odometry
  ros::Subscriber planar_cmd_sub_;    ///< and its command
  /// One per JointStatePublisherSpec, same index (all on joint_states).
  std::vector<CountedPublisher> plugin_joint_state_pubs_;
  ros::Subscriber cmd_vel_sub_;
  ros::Publisher tf_pub_;  ///< /tf, for the odom transform (a drive's or the planar move's)
  bool publish_odom_tf_ = false;
};

}  // namespace bullet_sim_node
