#include "topics/depth_camera_io.h"

#include "topics/camera_io.h"

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/PointField.h>
#include <sensor_msgs/image_encodings.h>

#include <boost/make_shared.hpp>

#include <cstring>
#include <memory>
#include <utility>

namespace bullet_sim_node {
namespace {

// A 640 x 480 depth image is 1.2 MB and its cloud 9.8 MB: a subscriber that falls behind
// loses frames rather than holding many of them in memory.
constexpr uint32_t kDepthQueueSize = 2;
constexpr uint32_t kCloudQueueSize = 1;
constexpr uint32_t kInfoQueueSize = 50;

sensor_msgs::ImagePtr toMsg(bullet_sim::DepthImageData* depth) {
  auto msg = boost::make_shared<sensor_msgs::Image>();
  msg->header.stamp.fromSec(depth->time_s);
  msg->width = static_cast<uint32_t>(depth->width);
  msg->height = static_cast<uint32_t>(depth->height);
  msg->encoding = sensor_msgs::image_encodings::TYPE_32FC1;
  msg->is_bigendian = 0;
  msg->step = static_cast<uint32_t>(sizeof(float) * depth->width);
  msg->data.resize(depth->depth_m.size() * sizeof(float));
  std::memcpy(msg->data.data(), depth->depth_m.data(), msg->data.size());
  return msg;
}

sensor_msgs::PointField field(const char* name, uint32_t offset) {
  sensor_msgs::PointField f;
  f.name = name;
  f.offset = offset;
  f.datatype = sensor_msgs::PointField::FLOAT32;
  f.count = 1;
  return f;
}

sensor_msgs::PointCloud2Ptr toMsg(bullet_sim::PointCloudData* cloud) {
  using bullet_sim::PointCloudData;
  auto msg = boost::make_shared<sensor_msgs::PointCloud2>();
  msg->header.stamp.fromSec(cloud->time_s);
  msg->height = static_cast<uint32_t>(cloud->height);
  msg->width = static_cast<uint32_t>(cloud->width);
  msg->fields = {field("x", 0), field("y", 4), field("z", 8),
                 field("rgb", PointCloudData::kRgbOffset)};
  msg->is_bigendian = false;
  msg->point_step = PointCloudData::kPointStep;
  msg->row_step = PointCloudData::kPointStep * msg->width;
  msg->is_dense = cloud->is_dense;
  msg->data.swap(cloud->data);
  return msg;
}

}  // namespace

void DepthCameraIo::addCamera(const std::string& robot, size_t index,
                              const bullet_sim::CameraSpec& camera, ros::NodeHandle& robot_nh,
                              const std::string& frame_id) {
  const bullet_sim::DepthSpec& spec = *camera.depth;
  Topics& topics = cameras_[{robot, index}];
  topics.frame_id = frame_id;
  topics.depth = CountedPublisher::advertise<sensor_msgs::Image>(
      robot_nh, cameraTopic(camera.camera_name, spec.depth_image_topic), kDepthQueueSize);
  topics.info = CountedPublisher::advertise<sensor_msgs::CameraInfo>(
      robot_nh, cameraTopic(camera.camera_name, spec.depth_info_topic), kInfoQueueSize);
  topics.points = CountedPublisher::advertise<sensor_msgs::PointCloud2>(
      robot_nh, cameraTopic(camera.camera_name, spec.point_cloud_topic), kCloudQueueSize);
}

void DepthCameraIo::removeRobot(const std::string& robot) {
  for (auto it = cameras_.lower_bound({robot, 0});
       it != cameras_.end() && it->first.first == robot;) {
    it = cameras_.erase(it);
  }
}

const DepthCameraIo::Topics* DepthCameraIo::find(const std::string& robot, size_t index) const {
  const auto it = cameras_.find({robot, index});
  return it == cameras_.end() ? nullptr : &it->second;
}

bool DepthCameraIo::depthWanted(const std::string& robot, size_t index) const {
  const Topics* topics = find(robot, index);
  return topics &&
         (topics->depth.hasSubscribers() || topics->points.hasSubscribers());
}

bool DepthCameraIo::infoWanted(const std::string& robot, size_t index) const {
  const Topics* topics = find(robot, index);
  return topics && topics->info.hasSubscribers();
}

void DepthCameraIo::publishInfo(const std::string& robot, size_t index,
                                const bullet_sim::CameraSpec& camera, double time_s) {
  if (!infoWanted(robot, index)) return;
  const Topics& topics = *find(robot, index);
  queue_.publish(topics.info.publisher(),
                 toMsg(bullet_sim::cameraInfo(camera, time_s), topics.frame_id));
}

void DepthCameraIo::publish(const std::string& robot, size_t index,
                            const bullet_sim::CameraSpec& camera,
                            bullet_sim::DepthImageData* depth, bullet_sim::ImageData* image,
                            bool image_kept) {
  const Topics* topics = find(robot, index);
  if (!topics) return;
  const bool points = topics->points.hasSubscribers();
  const bool depth_image = topics->depth.hasSubscribers();
  if (!points && !depth_image) return;
  // The stepping thread hands the frame over; the cloud and both messages are made on the
  // publishing thread (a 640 x 480 cloud is 9.8 MB to write).
  auto frame = std::make_shared<Frame>();
  frame->depth = std::move(*depth);
  if (points) {
    frame->camera = camera;
    frame->colours = image_kept ? *image : std::move(*image);
  }
  queue_.push([frame, points, depth_image, points_out = topics->points.publisher(),
               depth_out = topics->depth.publisher(), frame_id = topics->frame_id] {
    if (points) {
      bullet_sim::PointCloudData cloud;
      bullet_sim::makePointCloud(frame->camera, frame->depth, frame->colours, &cloud);
      sensor_msgs::PointCloud2Ptr msg = toMsg(&cloud);
      msg->header.frame_id = frame_id;
      points_out.publish(sensor_msgs::PointCloud2ConstPtr(std::move(msg)));
    }
    if (depth_image) {
      sensor_msgs::ImagePtr msg = toMsg(&frame->depth);
      msg->header.frame_id = frame_id;
      depth_out.publish(sensor_msgs::ImageConstPtr(std::move(msg)));
    }
  });
}

}  // namespace bullet_sim_node
