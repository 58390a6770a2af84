// The ROS side of the simulated cameras: image and camera_info publishers of every robot.
#pragma once

#include <bullet_sim/render/camera_renderer.h>
#include <bullet_sim/simulation.h>

#include "topics/counted_publisher.h"
#include "topics/depth_camera_io.h"
#include "topics/publish_queue.h"

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <sensor_msgs/CameraInfo.h>

#include <exception>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace bullet_sim_node {

/// `topic` under the camera's <cameraName> namespace, as Gazebo's camera plugins put it.
std::string cameraTopic(const std::string& camera_name, const std::string& topic);
/// The camera_info message of `info`, with `frame_id` (tf_prefix applied).
sensor_msgs::CameraInfoPtr toMsg(const bullet_sim::CameraInfoData& info,
                                 const std::string& frame_id);

/// Publishes `<cameraName>/<imageTopicName>` (sensor_msgs/Image) and
/// `<cameraName>/<cameraInfoTopicName>` (sensor_msgs/CameraInfo) for each camera of each
/// robot when the simulation says it is due, stamped with sim time. A frame is rendered
/// only while someone subscribes to the image, camera_info is filled only while someone
/// subscribes to it: cameras nobody watches cost nothing. One renderer (one scene with
/// every robot) serves all cameras. A depth camera's frame is rendered once for its
/// colour image and its depth topics (DepthCameraIo) alike.
class CameraIo {
 public:
  /// `sim` and `queue` (which the messages leave through) must outlive this object.
  /// A triggered camera's trigger topic asks `sim` for its frames (Simulation::triggerCamera)
  /// due the sim time that Gazebo's world steps on while its render thread draws a frame:
  /// the wall time of the last rendering round times `real_time_factor()` (the pace; 0,
  /// unpaced, asks for the next step).
  CameraIo(bullet_sim::Simulation& sim, PublishQueue& queue,
           std::function<double()> real_time_factor);
  CameraIo(const CameraIo&) = delete;
  CameraIo& operator=(const CameraIo&) = delete;

  /// Advertises the topics of a spawned robot's cameras, resolved in `robot_nh`; their
  /// frame ids go under `tf_prefix`. A camera the renderer cannot draw (bad size, fov or
  /// format) is reported and left out. A triggered camera subscribes to
  /// `<cameraName>/<triggerTopicName>` (std_msgs/Empty): one frame per message.
  void addRobot(const std::string& robot, const ros::NodeHandle& robot_nh,
                const std::string& tf_prefix);
  void removeRobot(const std::string& robot);

  /// Publishes the cameras due at one time (each due.kind == SensorKind::Camera, each
  /// camera once) that are watched; their frames are rendered together
  /// (CameraRenderer::renderTogether). A camera that cannot be rendered is reported and
  /// the others are published all the same.
  void publish(const std::vector<bullet_sim::DueSensor>& due);

 private:
  struct Topics {
    CountedPublisher image, info;
    ros::Subscriber trigger;  ///< a triggered camera's trigger topic
    std::string frame_id;
  };
  /// A due camera that someone watches, and its frame once rendered.
  struct Watched {
    const bullet_sim::DueSensor* due;
    Topics* topics;
    const bullet_sim::CameraSpec* camera;
    bool image_wanted, info_wanted, depth_wanted;
    bullet_sim::ImageData image;
    bullet_sim::DepthImageData depth;
    std::exception_ptr render_error;  ///< why the frame was not rendered, if it was not
  };

  /// The camera of `due` if someone subscribes to any of its topics.
  std::optional<Watched> watched(const bullet_sim::DueSensor& due);
  /// Publishes what `camera` has to publish once its frame is rendered (or reports why
  /// it was not).
  void publish(Watched* camera);

  void logNewRendererWarnings();

  bullet_sim::Simulation& sim_;
  PublishQueue& queue_;
  bullet_sim::CameraRenderer renderer_;
  DepthCameraIo depth_;  ///< the depth topics of the depth cameras among them
  std::map<std::string, std::vector<Topics>> cameras_;  ///< per robot, by camera index
  size_t warnings_logged_ = 0;
  std::function<double()> real_time_factor_;
  double render_wall_s_ = 0;  ///< the wall time the last round of frames took to render
};

}  // namespace bullet_sim_node
