#include "topics/robot_io.h"

#include "topics/conversions.h"
#include "topics/sensor_conversions.h"
#include "topics/tf_prefix.h"

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <optional>

namespace bullet_sim_node {
namespace {

// Outgoing messages kept per subscriber: at 100x real time a 200 Hz IMU sends 20000
// messages per wall second, and a short stall of a subscriber must not lose any.
constexpr uint32_t kQueueSize = 200;
// What tf2_ros's TransformBroadcaster queues on /tf.
constexpr uint32_t kTfQueueSize = 100;

struct Field {
  const char* name;
  double value;
};

/// The first non-finite field of a command, if any.
std::optional<Field> firstNonFiniteField(const geometry_msgs::Twist& command) {
  const Field fields[] = {{"linear.x", command.linear.x},   {"linear.y", command.linear.y},
                          {"linear.z", command.linear.z},   {"angular.x", command.angular.x},
                          {"angular.y", command.angular.y}, {"angular.z", command.angular.z}};
  for (const Field& field : fields)
    if (!std::isfinite(field.value)) return field;
  return std::nullopt;
}

}  // namespace

bool RobotIo::hasTopics(const bullet_sim::RobotSpec& spec) {
  return !spec.rays.empty() || !spec.imus.empty() || !spec.ranges.empty() ||
         !spec.block_lasers.empty() || !spec.bumpers.empty() || !spec.p3ds.empty() ||
         !spec.forces.empty() || !spec.f3ds.empty() || !spec.ft_sensors.empty() ||
         spec.diff_drive.has_value() || spec.planar_move.has_value() ||
         !spec.joint_state_publishers.empty();
}

RobotIo::RobotIo(bullet_sim::Simulation& sim, PublishQueue& queue, const std::string& robot,
                 const ros::NodeHandle& robot_nh, const std::string& tf_prefix,
                 bool joint_states)
    : sim_(sim), queue_(queue), robot_(robot), tf_prefix_(tf_prefix) {
  ros::NodeHandle nh(robot_nh);
  const bullet_sim::RobotSpec& spec = sim_.robotSpec(robot_);
  for (const bullet_sim::RaySpec& ray : spec.rays)
    scan_pubs_.push_back(
        CountedPublisher::advertise<sensor_msgs::LaserScan>(nh, ray.topic, kQueueSize));
  for (const bullet_sim::ImuSpec& imu : spec.imus)
    imu_pubs_.push_back(CountedPublisher::advertise<sensor_msgs::Imu>(nh, imu.topic, kQueueSize));
  for (const bullet_sim::RangeSpec& range : spec.ranges)
    range_pubs_.push_back(
        CountedPublisher::advertise<sensor_msgs::Range>(nh, range.topic, kQueueSize));
  for (const bullet_sim::BlockLaserSpec& laser : spec.block_lasers)
    block_laser_pubs_.push_back(
        CountedPublisher::advertise<sensor_msgs::PointCloud>(nh, laser.topic, kQueueSize));
  for (const bullet_sim::BumperSpec& bumper : spec.bumpers)
    bumper_pubs_.push_back(
        CountedPublisher::advertise<gazebo_msgs::ContactsState>(nh, bumper.topic, kQueueSize));
  if (joint_states && spec.joint_state_publishers.empty()) {
    joint_state_pub_ =
        CountedPublisher::advertise<sensor_msgs::JointState>(nh, "joint_states", kQueueSize);
  }
  for (const bullet_sim::P3dSpec& p3d : spec.p3ds)
    ground_truth_pubs_.push_back(
        CountedPublisher::advertise<nav_msgs::Odometry>(nh, p3d.topic, kQueueSize));
  for (size_t i = 0; i < spec.forces.size(); ++i)
    wrench_subs_.push_back(nh.subscribe<geometry_msgs::Wrench>(
        spec.forces[i].topic, 1,
        [this, i](const geometry_msgs::Wrench::ConstPtr& wrench) { onWrench(i, wrench); }));
  for (const bullet_sim::F3dSpec& f3d : spec.f3ds)
    f3d_pubs_.push_back(
        CountedPublisher::advertise<geometry_msgs::WrenchStamped>(nh, f3d.topic, kQueueSize));
  for (const bullet_sim::FtSensorSpec& ft : spec.ft_sensors)
    ft_pubs_.push_back(
        CountedPublisher::advertise<geometry_msgs::WrenchStamped>(nh, ft.topic, kQueueSize));
  if (spec.diff_drive) {
    odom_pub_ = CountedPublisher::advertise<nav_msgs::Odometry>(
        nh, spec.diff_drive->odometry_topic, kQueueSize);
    publish_odom_tf_ = spec.diff_drive->publish_odom_tf;
    if (publish_odom_tf_) tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", kTfQueueSize);
    cmd_vel_sub_ = nh.subscribe(spec.diff_drive->command_topic, 1, &RobotIo::onCmdVel, this,
                                ros::TransportHints().tcpNoDelay());
  }
  advertiseMotionPlugins(nh, spec);
}

void RobotIo::publish(const bullet_sim::DueSensor& due) {
  switch (due.kind) {
    case bullet_sim::SensorKind::Ray:
      if (wantsScan(due.index)) publishScan(due.index, sim_.readRay(robot_, due.index));
      break;
    case bullet_sim::SensorKind::Imu:
      if (due.index < imu_pubs_.size() && imu_pubs_[due.index].hasSubscribers()) {
        sensor_msgs::Imu imu = toMsg(sim_.readImu(robot_, due.index));
        imu.header.frame_id = resolveFrame(tf_prefix_, imu.header.frame_id);
        queue_.publish(imu_pubs_[due.index].publisher(), std::move(imu));
      }
      break;
    case bullet_sim::SensorKind::Odometry:
      publishOdometry();
      break;
    case bullet_sim::SensorKind::JointStates:
      if (joint_state_pub_.hasSubscribers())
        queue_.publish(joint_state_pub_.publisher(), toMsg(sim_.readJointStates(robot_)));
      break;
    case bullet_sim::SensorKind::GroundTruth:
      if (due.index < ground_truth_pubs_.size() && ground_truth_pubs_[due.index].hasSubscribers()) {
        bullet_sim::OdometryData truth = sim_.readGroundTruth(robot_, due.index);
        // As Gazebo's p3d: the frame under the tf_prefix, the body's link name as it is.
        truth.frame_id = resolveFrame(tf_prefix_, truth.frame_id);
        queue_.publish(ground_truth_pubs_[due.index].publisher(), toMsg(truth));
      }
      break;
    case bullet_sim::SensorKind::Camera:  // CameraIo publishes the cameras
      break;
    case bullet_sim::SensorKind::PlanarMoveOdometry:
    case bullet_sim::SensorKind::PluginJointStates:
      publishMotionPlugin(due);
      break;
    case bullet_sim::SensorKind::Range:
    case bullet_sim::SensorKind::BlockLaser:
    case bullet_sim::SensorKind::Bumper:
      publishRangeOrContacts(due);
      break;
    case bullet_sim::SensorKind::F3d:
    case bullet_sim::SensorKind::ForceTorque:
      publishWrench(due);
      break;
  }
}

bool RobotIo::wantsScan(size_t index) const {
  return index < scan_pubs_.size() && scan_pubs_[index].hasSubscribers();
}

void RobotIo::publishScan(size_t index, const bullet_sim::LaserScanData& data) {
  sensor_msgs::LaserScan scan = toMsg(data);
  scan.header.frame_id = resolveFrame(tf_prefix_, scan.header.frame_id);
  queue_.publish(scan_pubs_.at(index).publisher(), std::move(scan));
}

void RobotIo::publishOdometry() {
  const bool odom_wanted = odom_pub_.hasSubscribers();
  if (!odom_wanted && !publish_odom_tf_) return;
  bullet_sim::OdometryData odom = sim_.readOdometry(robot_);
  odom.frame_id = resolveFrame(tf_prefix_, odom.frame_id);
  odom.child_frame_id = resolveFrame(tf_prefix_, odom.child_frame_id);
  if (publish_odom_tf_) {
    tf2_msgs::TFMessage tf;
    tf.transforms.push_back(toTransformMsg(odom));
    queue_.publish(tf_pub_, std::move(tf));
  }
  if (odom_wanted) queue_.publish(odom_pub_.publisher(), toMsg(odom));
}

void RobotIo::onWrench(size_t index, const geometry_msgs::Wrench::ConstPtr& wrench) {
  const double values[6] = {wrench->force.x,  wrench->force.y,  wrench->force.z,
                            wrench->torque.x, wrench->torque.y, wrench->torque.z};
  for (const double v : values) {
    if (!std::isfinite(v)) {
      ROS_WARN_THROTTLE(5.0, "robot %s: dropped a %s wrench with a field that is %f",
                        robot_.c_str(), wrench_subs_[index].getTopic().c_str(), v);
      return;
    }
  }
  bullet_sim::Wrench w;
  w.force_n = Eigen::Vector3d(values[0], values[1], values[2]);
  w.torque_nm = Eigen::Vector3d(values[3], values[4], values[5]);
  sim_.setPluginWrench(robot_, index, w);
}

void RobotIo::publishWrench(const bullet_sim::DueSensor& due) {
  const bool f3d = due.kind == bullet_sim::SensorKind::F3d;
  const std::vector<CountedPublisher>& pubs = f3d ? f3d_pubs_ : ft_pubs_;
  if (due.index >= pubs.size() || !pubs[due.index].hasSubscribers()) return;
  bullet_sim::WrenchData wrench =
      f3d ? sim_.readF3d(robot_, due.index) : sim_.readForceTorque(robot_, due.index);
  // As Gazebo's plugins: the frame (frameName, or the child link) under the tf_prefix.
  wrench.frame_id = resolveFrame(tf_prefix_, wrench.frame_id);
  queue_.publish(pubs[due.index].publisher(), toMsg(wrench));
}

void RobotIo::publishRangeOrContacts(const bullet_sim::DueSensor& due) {
  using Kind = bullet_sim::SensorKind;
  const std::vector<CountedPublisher>& pubs = due.kind == Kind::Range        ? range_pubs_
                                              : due.kind == Kind::BlockLaser ? block_laser_pubs_
                                                                             : bumper_pubs_;
  if (due.index >= pubs.size() || !pubs[due.index].hasSubscribers()) return;
  const ros::Publisher& pub = pubs[due.index].publisher();
  if (due.kind == Kind::Range) {
    sensor_msgs::Range msg = toMsg(sim_.readRange(robot_, due.index));
    msg.header.frame_id = resolveFrame(tf_prefix_, msg.header.frame_id);
    queue_.publish(pub, std::move(msg));
  } else if (due.kind == Kind::BlockLaser) {
    sensor_msgs::PointCloud msg = toMsg(sim_.readBlockLaser(robot_, due.index));
    msg.header.frame_id = resolveFrame(tf_prefix_, msg.header.frame_id);
    queue_.publish(pub, std::move(msg));
  } else {
    gazebo_msgs::ContactsState msg = toMsg(sim_.readBumper(robot_, due.index));
    msg.header.frame_id = resolveFrame(tf_prefix_, msg.header.frame_id);
    queue_.publish(pub, std::move(msg));
  }
}

void RobotIo::onCmdVel(const geometry_msgs::Twist::ConstPtr& command) {
  if (const std::optional<Field> bad = firstNonFiniteField(*command)) {
    ROS_WARN_THROTTLE(5.0, "robot %s: dropped a %s command: %s is %f", robot_.c_str(),
                      cmd_vel_sub_.getTopic().c_str(), bad->name, bad->value);
    return;
  }
  sim_.setCmdVel(robot_, command->linear.x, command->angular.z);
}

}  // namespace bullet_sim_node
