#ifndef BULLET_SIM_SENSOR_DATA_H
#define BULLET_SIM_SENSOR_DATA_H

#include <array>
#include <string>
#include <vector>

#include "bullet_sim/types.h"

namespace bullet_sim {

enum class SensorKind {
  Ray, Imu, Camera, Odometry, JointStates, GroundTruth, Range, BlockLaser, Bumper,
  PlanarMoveOdometry,  ///< libgazebo_ros_planar_move.so's odometry (index 0)
  PluginJointStates,   ///< a libgazebo_ros_joint_state_publisher.so (index into its specs)
  F3d, ForceTorque
};

/// A sensor whose update period elapsed; index points into the robot spec's
/// vector of that kind (0 for Odometry and JointStates).
struct DueSensor {
  std::string robot;
  SensorKind kind;
  size_t index;
};

/// One planar scan, laid out as sensor_msgs/LaserScan.
struct LaserScanData {
  double time_s = 0;
  std::string frame_id;
  double angle_min = 0, angle_max = 0, angle_increment = 0, time_increment = 0, scan_time = 0,
         range_min = 0, range_max = 0;
  std::vector<float> ranges;       ///< +inf where nothing is hit within range_max
  std::vector<float> intensities;
};

/// One reading of a range sensor, laid out as sensor_msgs/Range.
struct RangeData {
  double time_s = 0;
  std::string frame_id;
  bool infrared = false;  ///< radiation_type INFRARED (1), else ULTRASOUND (0)
  float field_of_view = 0, min_range = 0, max_range = 0;
  float range = 0;  ///< the nearest ray's range (+ noise), max_range when none hits
};

/// A block laser's points, laid out as sensor_msgs/PointCloud with one channel (its
/// intensities, unnamed as in Gazebo's plugin).
struct BlockLaserCloudData {
  double time_s = 0;
  std::string frame_id;
  std::vector<Eigen::Vector3f> points;  ///< in the sensor frame
  std::vector<float> intensities;       ///< one per point
};

/// What touches one collision, laid out as gazebo_msgs/ContactState.
struct ContactStateData {
  std::string collision1_name, collision2_name;  ///< "model::link::collision"; 1 is the sensor's
  /// Force (N) and torque (N m, about the body's centre of mass) on collision 1 at each
  /// point, in the axes of its link, as Gazebo's ODE reports them
  std::vector<Eigen::Vector3d> forces, torques;
  Eigen::Vector3d total_force{0, 0, 0}, total_torque{0, 0, 0};
  std::vector<Eigen::Vector3d> positions, normals;  ///< world frame; normals point into collision 1
  std::vector<double> depths;
};

/// A bumper's reading, laid out as gazebo_msgs/ContactsState: a state per touching collision.
struct ContactsData {
  double time_s = 0;
  std::string frame_id;
  std::vector<ContactStateData> states;
};

/// One IMU reading, in the IMU (link) frame.
struct ImuData {
  double time_s = 0;
  std::string frame_id;
  Eigen::Quaterniond orientation{1, 0, 0, 0};  ///< link orientation in the world
  Eigen::Vector3d angular_velocity{0, 0, 0};
  Eigen::Vector3d linear_acceleration{0, 0, 0};  ///< proper acceleration: +g on z at rest
  double orientation_cov = 0, angular_velocity_cov = 0, linear_acceleration_cov = 0;
};

/// Odometry of the diff drive, laid out as nav_msgs/Odometry.
struct OdometryData {
  double time_s = 0;
  std::string frame_id, child_frame_id;
  Pose3 pose;             ///< child (robot base) in the odometry frame
  Twist3 twist_in_child;  ///< body-frame twist, as nav_msgs/Odometry wants
  /// Row-major 6 x 6 covariances (x, y, z, roll, pitch, yaw), as nav_msgs/Odometry has them.
  std::array<double, 36> pose_covariance{}, twist_covariance{};
};

/// A force and a torque, laid out as geometry_msgs/WrenchStamped (its frame as the
/// plugin names it, before any tf_prefix).
struct WrenchData {
  double time_s = 0;
  std::string frame_id;
  Eigen::Vector3d force_n{0, 0, 0};
  Eigen::Vector3d torque_nm{0, 0, 0};
};

/// State of every non-fixed joint, laid out as sensor_msgs/JointState.
struct JointStateData {
  double time_s = 0;
  std::vector<std::string> names;
  std::vector<double> positions, velocities, efforts;
};

/// World pose of one URDF link.
struct LinkPose {
  std::string link;
  Pose3 pose;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_SENSOR_DATA_H
