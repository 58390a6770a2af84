// The ROS side of the simulated depth cameras: depth image, its camera_info and points.
#pragma once

#include <bullet_sim/render/camera_renderer.h>
#include <bullet_sim/render/depth_camera.h>

#include <ros/node_handle.h>
#include "topics/counted_publisher.h"
#include "topics/publish_queue.h"

#include <ros/publisher.h>

#include <map>
#include <string>
#include <utility>

namespace bullet_sim_node {

/// Publishes what Gazebo's depth plugins add to a camera: `<cameraName>/<depthImageTopicName>`
/// (sensor_msgs/Image, 32FC1), `<cameraName>/<depthImageCameraInfoTopicName>` and
/// `<cameraName>/<pointCloudTopicName>` (sensor_msgs/PointCloud2). CameraIo renders the
/// frame (one pass gives colour and depth) and hands it here; the colour image and its
/// camera_info stay CameraIo's.
class DepthCameraIo {
 public:
  /// Messages leave through `queue`, which must outlive this object.
  explicit DepthCameraIo(PublishQueue& queue) : queue_(queue) {}

  /// Advertises the depth topics of camera `index` of `robot` (camera.depth must be set)
  /// in `robot_nh`, stamped with `frame_id` (tf_prefix already applied).
  void addCamera(const std::string& robot, size_t index, const bullet_sim::CameraSpec& camera,
                 ros::NodeHandle& robot_nh, const std::string& frame_id);
  void removeRobot(const std::string& robot);

  /// True when someone subscribes to the depth image or the points: the frame then needs
  /// its depth buffer.
  bool depthWanted(const std::string& robot, size_t index) const;
  /// True when someone subscribes to the depth camera_info.
  bool infoWanted(const std::string& robot, size_t index) const;

  /// Publishes the depth camera_info, stamped `time_s`, if someone subscribes.
  void publishInfo(const std::string& robot, size_t index, const bullet_sim::CameraSpec& camera,
                   double time_s);
  /// Publishes the depth image and the point cloud (coloured from `image`) of a rendered
  /// frame to whichever of them someone subscribes. `depth` is moved out; when the cloud is
  /// wanted, `image` is copied if `image_kept` (the caller publishes it too), else moved
  /// out. The cloud and the messages are made on the publishing thread, and leave in the
  /// queue's order (before what is queued after this call).
  void publish(const std::string& robot, size_t index, const bullet_sim::CameraSpec& camera,
               bullet_sim::DepthImageData* depth, bullet_sim::ImageData* image,
               bool image_kept);

 private:
  /// What the publishing thread makes a depth frame's messages from.
  struct Frame {
    bullet_sim::DepthImageData depth;
    bullet_sim::CameraSpec camera;   ///< for the cloud only
    bullet_sim::ImageData colours;   ///< for the cloud only
  };
  struct Topics {
    CountedPublisher depth, info, points;
    std::string frame_id;
  };
  const Topics* find(const std::string& robot, size_t index) const;

  PublishQueue& queue_;
  std::map<std::pair<std::string, size_t>, Topics> cameras_;
};

}  // namespace bullet_sim_node
