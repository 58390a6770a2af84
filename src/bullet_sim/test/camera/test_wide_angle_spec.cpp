// <sensor type="wideanglecamera"> as the loader reads it: the autorace lens's values, SDF's
// defaults for a left-out <lens>, and one variant of wide_angle_robot.urdf per bad value,
// with the message naming the element and the value asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "wide_angle_fixture.h"

namespace {

using bullet_sim::CameraSpec;
using bullet_sim::LoadError;
using bullet_sim::parseRobot;
using bullet_sim_test::wideAngleFixtureWith;

constexpr const char* kSource = "wide_angle_robot.urdf";
const std::string kCameraWhere = std::string(kSource) +
    ": <gazebo reference=\"camera_link\"> <sensor name=\"camera\"> <camera>";
const std::string kLensWhere = kCameraWhere + " <lens>";

std::string loadErrorOf(const std::string& urdf) {
  try {
    parseRobot(urdf, kSource);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

TEST(WideAngleSpec, TheLensAndThePluginAreRead) {
  const bullet_sim::RobotSpec spec = parseRobot(wideAngleFixtureWith(), kSource);
  ASSERT_EQ(spec.cameras.size(), 1u);
  for (const std::string& w : spec.warnings) {
    EXPECT_EQ(w.find("wideanglecamera"), std::string::npos) << w;
  }
  const CameraSpec& c = spec.cameras[0];
  EXPECT_EQ(c.image_topic, "image");
  EXPECT_EQ(c.info_topic, "camera_info");
  EXPECT_EQ(c.frame_id, "camera_link");
  EXPECT_DOUBLE_EQ(c.horizontal_fov_rad, 4.0);
  EXPECT_FALSE(c.depth);
  ASSERT_TRUE(c.lens);
  EXPECT_EQ(c.lens->type, "custom");
  EXPECT_DOUBLE_EQ(c.lens->c1, 1.05);
  EXPECT_DOUBLE_EQ(c.lens->c2, 4);
  EXPECT_DOUBLE_EQ(c.lens->c3, 0);
  EXPECT_DOUBLE_EQ(c.lens->f, 1.0);
  EXPECT_EQ(c.lens->fun, "tan");
  EXPECT_TRUE(c.lens->scale_to_hfov);
  EXPECT_DOUBLE_EQ(c.lens->cutoff_angle_rad, 3.1415);
  EXPECT_EQ(c.lens->env_texture_size, 256);
}

TEST(WideAngleSpec, ALeftOutLensIsSdfsStereographicDefault) {
  std::string urdf = wideAngleFixtureWith({{"<horizontal_fov>4.0<", "<horizontal_fov>3.0<"}});
  const size_t from = urdf.find("        <lens>");
  const size_t to = urdf.find("</lens>") + std::string("</lens>\n").size();
  urdf.erase(from, to - from);
  const CameraSpec c = parseRobot(urdf, kSource).cameras.at(0);
  ASSERT_TRUE(c.lens);
  EXPECT_EQ(c.lens->type, "stereographic");
  EXPECT_TRUE(c.lens->scale_to_hfov);
  EXPECT_DOUBLE_EQ(c.lens->cutoff_angle_rad, 1.5707);
  EXPECT_EQ(c.lens->env_texture_size, 256);
}

TEST(WideAngleSpec, AWideAngleCameraWithAnotherPluginIsLeftOutWithAWarning) {
  const bullet_sim::RobotSpec spec = parseRobot(
      wideAngleFixtureWith({{"libgazebo_ros_camera.so", "libgazebo_ros_multicamera.so"}}),
      kSource);
  EXPECT_TRUE(spec.cameras.empty());
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0], "plugin 'libgazebo_ros_multicamera.so' in wideanglecamera sensor "
                              "'camera' on link 'camera_link' is not supported: ignored");
}

struct BadValue {
  std::string from, to, message;
};

TEST(WideAngleSpec, EveryBadLensValueIsALoadErrorNamingElementAndValue) {
  const std::string fw = kLensWhere + " <custom_function>";
  const BadValue cases[] = {
      {"<type>custom<", "<type>fisheye<",
       kLensWhere + ": <type>: 'fisheye' is not gnomonical, stereographic, equidistant, "
                    "equisolid_angle, orthographic or custom"},
      {"<fun>tan<", "<fun>cos<", fw + " <fun>: 'cos' is not sin, tan or id"},
      {"<c2>4<", "<c2>0<", fw + " <c2>: '0' must be finite and not 0"},
      {"<c1>1.05<", "<c1>wide<", fw + " <c1>: 'wide' is not a number"},
      {"<cutoff_angle>3.1415<", "<cutoff_angle>4<",
       kLensWhere + " <cutoff_angle>: '4' must be in (0, pi] radians"},
      {"<env_texture_size>256<", "<env_texture_size>3<",
       kLensWhere + " <env_texture_size>: '3' is not a pixel count in 4..2048"},
      {"<scale_to_hfov>true<", "<scale_to_hfov>maybe<",
       kLensWhere + " <scale_to_hfov>: 'maybe' is not a boolean (true/false/1/0)"},
      {"<horizontal_fov>4.0<", "<horizontal_fov>7<",
       kCameraWhere + " <horizontal_fov>: '7' must be in (0, 2 pi] radians"},
  };
  for (const BadValue& c : cases) {
    EXPECT_EQ(loadErrorOf(wideAngleFixtureWith({{c.from, c.to}})), c.message) << c.to;
  }
}

TEST(WideAngleSpec, AnHfovTheLensCannotMapIsALoadError) {
  // A gnomonical (pinhole) lens reaches 90 degrees off the axis only at infinity.
  const std::string message = loadErrorOf(wideAngleFixtureWith(
      {{"<type>custom</type>", "<type>gnomonical</type>"}}));
  EXPECT_EQ(message, kLensWhere + ": <horizontal_fov>: '4.000000' is beyond what lens "
                                  "'gnomonical' maps (scale_to_hfov)");
}

}  // namespace
