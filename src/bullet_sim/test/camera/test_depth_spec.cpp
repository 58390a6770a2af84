// <sensor type="depth"> with Gazebo's depth plugins as the loader reads it: the parameters
// and their defaults, and one generated variant of depth_camera_robot.urdf per bad value,
// with the message asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "depth_fixture.h"

namespace {

using bullet_sim_test::depthFixtureText;
using bullet_sim_test::depthFixtureWith;

using bullet_sim::CameraSpec;
using bullet_sim::LoadError;
using bullet_sim::parseRobot;
using bullet_sim::RobotSpec;

constexpr const char* kSource = "depth_camera_robot.urdf";
const std::string kWhere = std::string(kSource) +
    ": <gazebo reference=\"camera_link\"> <sensor name=\"kinect\">";
const std::string kPluginWhere =
    kWhere + " <plugin filename=\"libgazebo_ros_openni_kinect.so\">";

std::string loadErrorOf(const std::string& urdf) {
  try {
    parseRobot(urdf, kSource);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

/// The fixture with the plugin's parameters from <cameraName> to <updateRate> left out.
std::string withoutPluginParameters(const std::string& file) {
  std::string text = depthFixtureWith("libgazebo_ros_openni_kinect.so", file);
  const size_t from = text.find("        <cameraName>");
  const size_t to = text.find("      </plugin>");
  return text.erase(from, to - from);
}

TEST(DepthSpec, TheKinectPluginsParametersAreRead) {
  const RobotSpec spec = parseRobot(depthFixtureText(), kSource);
  ASSERT_EQ(spec.cameras.size(), 1u);
  const CameraSpec& c = spec.cameras[0];
  EXPECT_EQ(c.name, "kinect");
  EXPECT_EQ(c.link, "camera_link");
  EXPECT_EQ(c.camera_name, "kinect");
  EXPECT_EQ(c.image_topic, "rgb/image_raw");
  EXPECT_EQ(c.info_topic, "rgb/camera_info");
  EXPECT_EQ(c.frame_id, "camera_depth_optical_frame");
  EXPECT_EQ(c.width, 160);
  EXPECT_EQ(c.height, 120);
  EXPECT_DOUBLE_EQ(c.horizontal_fov_rad, 1.0472);
  EXPECT_DOUBLE_EQ(c.clip_near_m, 0.05);
  EXPECT_DOUBLE_EQ(c.clip_far_m, 8.0);
  EXPECT_DOUBLE_EQ(c.update_rate_hz, 10);
  ASSERT_TRUE(c.depth.has_value());
  EXPECT_EQ(c.depth->plugin, "libgazebo_ros_openni_kinect.so");
  EXPECT_EQ(c.depth->depth_image_topic, "depth/image_raw");
  EXPECT_EQ(c.depth->depth_info_topic, "depth/camera_info");
  EXPECT_EQ(c.depth->point_cloud_topic, "depth/points");
  EXPECT_DOUBLE_EQ(c.depth->cutoff_m, 0.1);
  EXPECT_DOUBLE_EQ(c.depth->cutoff_max_m, 6.0);
  EXPECT_TRUE(spec.warnings.empty()) << spec.warnings.front();
}

TEST(DepthSpec, TheKinectPluginsDefaultsAreGazebos) {
  const RobotSpec spec =
      parseRobot(withoutPluginParameters("libgazebo_ros_openni_kinect.so"), kSource);
  const CameraSpec& c = spec.cameras.at(0);
  EXPECT_EQ(c.camera_name, "camera");
  EXPECT_EQ(c.image_topic, "ir/image_raw");
  EXPECT_EQ(c.info_topic, "ir/camera_info");
  EXPECT_EQ(c.frame_id, "camera_link");
  EXPECT_EQ(c.depth->depth_image_topic, "depth/image_raw");
  EXPECT_EQ(c.depth->depth_info_topic, "depth/camera_info");
  EXPECT_EQ(c.depth->point_cloud_topic, "points");
  EXPECT_DOUBLE_EQ(c.depth->cutoff_m, 0.4);
  EXPECT_DOUBLE_EQ(c.depth->cutoff_max_m, 5.0);
  EXPECT_DOUBLE_EQ(c.update_rate_hz, 10);  // the sensor's <update_rate>
}

TEST(DepthSpec, TheDepthCameraPluginHasNoUpperCutoff) {
  const RobotSpec spec =
      parseRobot(withoutPluginParameters("libgazebo_ros_depth_camera.so"), kSource);
  const CameraSpec& c = spec.cameras.at(0);
  EXPECT_EQ(c.depth->plugin, "libgazebo_ros_depth_camera.so");
  EXPECT_EQ(c.image_topic, "ir/image_raw");
  EXPECT_DOUBLE_EQ(c.depth->cutoff_m, 0.4);
  EXPECT_TRUE(std::isinf(c.depth->cutoff_max_m));

  const RobotSpec with_max = parseRobot(
      depthFixtureWith("libgazebo_ros_openni_kinect.so", "libgazebo_ros_depth_camera.so"), kSource);
  ASSERT_EQ(with_max.warnings.size(), 1u);
  EXPECT_EQ(with_max.warnings[0],
            "<gazebo reference=\"camera_link\"> <sensor name=\"kinect\"> <plugin "
            "filename=\"libgazebo_ros_depth_camera.so\"> <pointCloudCutoffMax>: not a parameter "
            "of libgazebo_ros_depth_camera.so (it has no upper cutoff): ignored");
  EXPECT_TRUE(std::isinf(with_max.cameras.at(0).depth->cutoff_max_m));
}

TEST(DepthSpec, ADepthSensorWithAnotherPluginIsLeftOutWithAWarning) {
  const RobotSpec spec = parseRobot(
      depthFixtureWith("libgazebo_ros_openni_kinect.so", "libgazebo_ros_camera.so"), kSource);
  EXPECT_TRUE(spec.cameras.empty());
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0], "plugin 'libgazebo_ros_camera.so' in depth sensor 'kinect' on "
                              "link 'camera_link' is not supported: ignored");
}

struct BadValue {
  const char* from;
  const char* to;
  std::string message;
};

TEST(DepthSpec, EveryBadValueIsALoadErrorNamingSensorElementAndValue) {
  const std::string cw = kWhere + " <camera>";
  const BadValue cases[] = {
      {"<pointCloudCutoff>0.1<", "<pointCloudCutoff>near<",
       kPluginWhere + " <pointCloudCutoff>: 'near' is not a number"},
      {"<pointCloudCutoff>0.1<", "<pointCloudCutoff>-0.5<",
       kPluginWhere + " <pointCloudCutoff>: '-0.5' must be >= 0"},
      {"<pointCloudCutoffMax>6.0<", "<pointCloudCutoffMax>0.05<",
       kPluginWhere + " <pointCloudCutoffMax>: '0.05' must be above <pointCloudCutoff> 0.100000"},
      {"<horizontal_fov>1.0472<", "<horizontal_fov>3.5<",
       cw + " <horizontal_fov>: '3.5' must be in (0, pi) radians"},
      {"<width>160<", "<width>0<", cw + " <image> <width>: '0' is not a pixel count in 1..16384"},
      {"<height>120<", "<height>12.5<",
       cw + " <image> <height>: '12.5' is not a pixel count in 1..16384"},
      {"<format>R8G8B8<", "<format>RGBA_INT8<",
       cw + " <image> <format>: 'RGBA_INT8' is not R8G8B8, B8G8R8, L8, R16G16B16 or L16 (or "
           "RGB_INT8, BGR_INT8, L_INT8, RGB_INT16, L_INT16)"},
      {"<near>0.05<", "<near>0<", cw + " <clip> <near>: '0' must be > 0"},
      {"<far>8.0<", "<far>0.01<", cw + " <clip> <far>: '0.01' must be finite and above <near>"},
      {"<updateRate>10<", "<updateRate>fast<",
       kWhere + " <plugin> <updateRate>: 'fast' is not a number"},
  };
  for (const BadValue& c : cases) {
    EXPECT_EQ(loadErrorOf(depthFixtureWith(c.from, c.to)), c.message) << c.to;
  }
}

TEST(DepthSpec, ADepthSensorWithoutCameraIsALoadError) {
  std::string text = depthFixtureText();
  const size_t from = text.find("      <camera>");
  const size_t to = text.find("</camera>") + std::string("</camera>\n").size();
  text.erase(from, to - from);
  EXPECT_EQ(loadErrorOf(text), kWhere + ": needs a <camera> element");
}

}  // namespace
