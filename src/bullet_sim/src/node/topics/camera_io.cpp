#include "topics/camera_io.h"

#include "topics/tf_prefix.h"

#include <bullet_sim/errors.h>

#include <ros/console.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Empty.h>

#include <boost/make_shared.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <stdexcept>
#include <utility>

namespace bullet_sim_node {
namespace {

// Outgoing messages kept per subscriber. An image is 0.9 MB at 640 x 480: a few absorb a
// short stall of a subscriber; one that falls further behind loses frames, not memory.
constexpr uint32_t kImageQueueSize = 5;
constexpr uint32_t kInfoQueueSize = 50;
// Triggers kept until the simulation loop reads them: a burst of them is not lost.
constexpr uint32_t kTriggerQueueSize = 10;

sensor_msgs::ImagePtr toMsg(bullet_sim::ImageData* image) {
  auto msg = boost::make_shared<sensor_msgs::Image>();
  msg->header.stamp.fromSec(image->time_s);
  msg->header.frame_id = image->frame_id;
  msg->width = static_cast<uint32_t>(image->width);
  msg->height = static_cast<uint32_t>(image->height);
  msg->encoding = image->encoding;
  msg->is_bigendian = 0;
  msg->step = static_cast<uint32_t>(image->step);
  msg->data.swap(image->data);
  return msg;
}

}  // namespace

std::string cameraTopic(const std::string& camera_name, const std::string& topic) {
  return camera_name.empty() ? topic : camera_name + "/" + topic;
}

sensor_msgs::CameraInfoPtr toMsg(const bullet_sim::CameraInfoData& info,
                                 const std::string& frame_id) {
  auto msg = boost::make_shared<sensor_msgs::CameraInfo>();
  msg->header.stamp.fromSec(info.time_s);
  msg->header.frame_id = frame_id;
  msg->width = static_cast<uint32_t>(info.width);
  msg->height = static_cast<uint32_t>(info.height);
  msg->distortion_model = info.distortion_model;
  msg->D.assign(info.D.begin(), info.D.end());
  std::copy(info.K.begin(), info.K.end(), msg->K.begin());
  std::copy(info.R.begin(), info.R.end(), msg->R.begin());
  std::copy(info.P.begin(), info.P.end(), msg->P.begin());
  return msg;
}

CameraIo::CameraIo(bullet_sim::Simulation& sim, PublishQueue& queue,
                   std::function<double()> real_time_factor)
    : sim_(sim),
      queue_(queue),
      renderer_(sim),
      depth_(queue),
      real_time_factor_(std::move(real_time_factor)) {
  logNewRendererWarnings();
}

void CameraIo::addRobot(const std::string& robot, const ros::NodeHandle& robot_nh,
                        const std::string& tf_prefix) {
  ros::NodeHandle nh(robot_nh);
  std::vector<Topics>& topics = cameras_[robot];
  topics.clear();
  for (const bullet_sim::CameraSpec& camera : sim_.robotSpec(robot).cameras) {
    topics.emplace_back();
    topics.back().frame_id = resolveFrame(tf_prefix, camera.frame_id);
    try {
      bullet_sim::validateCamera(camera);
    } catch (const bullet_sim::LoadError& error) {
      ROS_ERROR("robot %s: %s: not published", robot.c_str(), error.what());
      continue;
    }
    topics.back().image = CountedPublisher::advertise<sensor_msgs::Image>(
        nh, cameraTopic(camera.camera_name, camera.image_topic), kImageQueueSize);
    topics.back().info = CountedPublisher::advertise<sensor_msgs::CameraInfo>(
        nh, cameraTopic(camera.camera_name, camera.info_topic), kInfoQueueSize);
    const size_t index = topics.size() - 1;
    if (camera.depth) depth_.addCamera(robot, index, camera, nh, topics.back().frame_id);
    if (!camera.trigger_topic.empty()) {
      topics.back().trigger = nh.subscribe<std_msgs::Empty>(
          cameraTopic(camera.camera_name, camera.trigger_topic), kTriggerQueueSize,
          [this, robot, index](const std_msgs::Empty::ConstPtr&) {
            try {
              // Gazebo's world steps on while its render thread draws the frame.
              const double rtf = std::max(0.0, real_time_factor_());
              sim_.triggerCamera(robot, index, render_wall_s_ * rtf);
            } catch (const std::out_of_range&) {  // the robot was deleted meanwhile
            }
          });
    }
  }
}

void CameraIo::removeRobot(const std::string& robot) {
  cameras_.erase(robot);
  depth_.removeRobot(robot);
}

void CameraIo::publish(const std::vector<bullet_sim::DueSensor>& due) {
  std::vector<Watched> cameras;
  cameras.reserve(due.size());
  for (const bullet_sim::DueSensor& sensor : due) {
    if (std::optional<Watched> camera = watched(sensor)) cameras.push_back(std::move(*camera));
  }
  // Frames are rendered for the image and depth topics; camera_info needs none.
  std::vector<bullet_sim::CameraFrame> frames;
  std::vector<Watched*> rendered;
  for (Watched& camera : cameras) {
    if (!camera.image_wanted && !camera.depth_wanted) continue;
    frames.push_back({camera.due->robot, camera.due->index, &camera.image,
                      camera.depth_wanted ? &camera.depth : nullptr, nullptr});
    rendered.push_back(&camera);
  }
  if (!frames.empty()) {
    const auto start = std::chrono::steady_clock::now();
    renderer_.renderTogether(&frames);
    render_wall_s_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (size_t i = 0; i < frames.size(); ++i) rendered[i]->render_error = frames[i].error;
  }
  for (Watched& camera : cameras) publish(&camera);
  logNewRendererWarnings();
}

std::optional<CameraIo::Watched> CameraIo::watched(const bullet_sim::DueSensor& due) {
  const auto robot = cameras_.find(due.robot);
  if (robot == cameras_.end() || due.index >= robot->second.size()) return std::nullopt;
  Topics& topics = robot->second[due.index];
  Watched camera{&due, &topics, &sim_.robotSpec(due.robot).cameras.at(due.index),
                 topics.image.hasSubscribers(), topics.info.hasSubscribers(),
                 depth_.depthWanted(due.robot, due.index), {}, {}, nullptr};
  if (!camera.image_wanted && !camera.info_wanted && !camera.depth_wanted &&
      !depth_.infoWanted(due.robot, due.index)) {
    return std::nullopt;
  }
  return camera;
}

void CameraIo::publish(Watched* camera) {
  const bullet_sim::DueSensor& due = *camera->due;
  Topics& topics = *camera->topics;
  if (camera->info_wanted) {
    queue_.publish(topics.info.publisher(),
                   toMsg(bullet_sim::cameraInfo(*camera->camera, sim_.timeS()), topics.frame_id));
  }
  depth_.publishInfo(due.robot, due.index, *camera->camera, sim_.timeS());
  if (!camera->image_wanted && !camera->depth_wanted) return;
  try {
    if (camera->render_error) std::rethrow_exception(camera->render_error);
    // The cloud takes its colours from the frame before the image message takes its bytes
    // (a copy of them when the image is published too).
    if (camera->depth_wanted) {
      depth_.publish(due.robot, due.index, *camera->camera, &camera->depth, &camera->image,
                     camera->image_wanted);
    }
    if (!camera->image_wanted) return;
    sensor_msgs::ImagePtr image = toMsg(&camera->image);
    image->header.frame_id = topics.frame_id;
    queue_.publish(topics.image.publisher(), std::move(image));
  } catch (const std::exception& error) {
    ROS_ERROR_THROTTLE(5.0, "robot %s: camera '%s' not rendered: %s", due.robot.c_str(),
                       camera->camera->name.c_str(), error.what());
  }
}

void CameraIo::logNewRendererWarnings() {
  const std::vector<std::string>& warnings = renderer_.warnings();
  for (; warnings_logged_ < warnings.size(); ++warnings_logged_)
    ROS_WARN("camera: %s", warnings[warnings_logged_].c_str());
}

}  // namespace bullet_sim_node
