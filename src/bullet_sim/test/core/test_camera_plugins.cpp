// The camera plugins' parameters: libgazebo_ros_multicamera.so (a camera per <camera> named
// left or right), the triggered cameras (frames only when asked), <noise>, <distortion>,
// 16-bit formats and camera_info's distortion and baseline, read from SDF as Gazebo does.
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"

using namespace bullet_sim;

namespace {

const UriResolver kNoPaths{ResourcePaths{}};

/// A static model holding `sensor` in link 'l', as a spawned SDF model.
RobotSpec modelWith(const std::string& sensor) {
  return parseSdfModelString("<sdf version='1.6'><model name='m'><static>true</static>"
                             "<link name='l'>" + sensor + "</link></model></sdf>",
                             "m.sdf", kNoPaths);
}

std::string cameraElement(const std::string& name, const std::string& inside) {
  return "<camera name='" + name + "'><horizontal_fov>1.0</horizontal_fov><image><width>64"
         "</width><height>48</height></image>" + inside + "</camera>";
}

const std::string kMulticamera =
    "<sensor type='multicamera' name='stereo'><pose>0 0 1 0 0 0</pose>"
    "<update_rate>0.1</update_rate>" + cameraElement("left", "") +
    cameraElement("right", "<pose>0 -0.07 0 0 0 0</pose>") +
    cameraElement("middle", "") +
    "<plugin name='p' filename='libgazebo_ros_multicamera.so'><cameraName>stereo/camera"
    "</cameraName><frameName>left_optical</frameName><hackBaseline>0.07</hackBaseline>"
    "</plugin></sensor>";

}  // namespace

TEST(CameraPlugins, AMulticameraPublishesItsLeftAndRightCamerasUnderTheCameraName) {
  const RobotSpec spec = modelWith(kMulticamera);
  ASSERT_EQ(spec.cameras.size(), 2u);  // 'middle' is neither left nor right: not published
  const CameraSpec& left = spec.cameras[0];
  const CameraSpec& right = spec.cameras[1];
  EXPECT_EQ(left.camera_name, "stereo/camera/left");
  EXPECT_EQ(right.camera_name, "stereo/camera/right");
  EXPECT_EQ(left.image_topic, "image_raw");
  EXPECT_EQ(left.frame_id, "left_optical");
  EXPECT_EQ(right.frame_id, "left_optical");  // Gazebo's plugin gives both the frameName
  EXPECT_DOUBLE_EQ(left.hack_baseline_m, 0);
  EXPECT_DOUBLE_EQ(right.hack_baseline_m, 0.07);
  EXPECT_DOUBLE_EQ(left.update_rate_hz, 0.1);
  EXPECT_TRUE(left.pose_in_link.position.isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(right.pose_in_link.position.isApprox(Eigen::Vector3d(0, -0.07, 1)));
  bool warned = false;
  for (const std::string& w : spec.warnings) {
    warned |= w.find("<camera name=\"middle\">") != std::string::npos;
  }
  EXPECT_TRUE(warned);
}

TEST(CameraPlugins, ATriggeredCameraHasATriggerTopicAndIsDueOnlyWhenTriggered) {
  const std::string sensor =
      "<sensor type='camera' name='cam'><update_rate>100</update_rate>" +
      cameraElement("head", "") +
      "<plugin name='p' filename='libgazebo_ros_triggered_camera.so'><cameraName>camera1"
      "</cameraName></plugin></sensor>";
  WorldSpec world;
  world.models.push_back({"m", modelWith(sensor), Pose3()});
  ASSERT_EQ(world.models[0].spec.cameras.size(), 1u);
  EXPECT_EQ(world.models[0].spec.cameras[0].trigger_topic, "image_trigger");
  Simulation sim(world, SimConfig{});
  const auto cameraDue = [&sim]() {
    int n = 0;
    for (const DueSensor& d : sim.step()) n += d.kind == SensorKind::Camera;
    return n;
  };
  int frames = 0;
  for (int i = 0; i < 100; ++i) frames += cameraDue();  // 0.1 s: 10 periods of 100 Hz
  EXPECT_EQ(frames, 0);
  sim.triggerCamera("m", 0);
  sim.triggerCamera("m", 0);
  EXPECT_EQ(cameraDue(), 1);
  EXPECT_EQ(cameraDue(), 1);
  for (int i = 0; i < 100; ++i) frames += cameraDue();
  EXPECT_EQ(frames, 0);
  EXPECT_THROW(sim.triggerCamera("m", 1), std::out_of_range);
}

TEST(CameraPlugins, ATriggeredFrameAskedWithADelayIsDueThatMuchSimTimeLater) {
  // The node asks for a frame 4.5 ms of sim time on (a render's wall time at real time):
  // with steps of 1 ms it is due at the 5th step, the first that ends 4.5 ms on, and a
  // stretch of up to 100 steps stops there. A second frame asked 2 ms after the first,
  // without a delay, is due at the next step and comes first.
  const std::string sensor =
      "<sensor type='camera' name='cam'>" + cameraElement("head", "") +
      "<plugin name='p' filename='libgazebo_ros_triggered_camera.so'/></sensor>";
  WorldSpec world;
  world.models.push_back({"m", modelWith(sensor), Pose3()});
  SimConfig config;
  config.physics_step_s = 0.001;
  Simulation sim(world, config);
  sim.triggerCamera("m", 0, 0.0045);
  unsigned taken = 0;
  EXPECT_TRUE(sim.stepToNextReading(2, &taken).empty());
  EXPECT_EQ(taken, 2u);
  sim.triggerCamera("m", 0);
  std::vector<DueSensor> due = sim.stepToNextReading(100, &taken);
  EXPECT_EQ(taken, 1u);  // step 3: the frame asked without a delay
  ASSERT_EQ(due.size(), 1u);
  EXPECT_EQ(due[0].kind, SensorKind::Camera);
  due = sim.stepToNextReading(100, &taken);
  EXPECT_EQ(taken, 2u);  // step 5, 5 ms: the delayed frame
  ASSERT_EQ(due.size(), 1u);
  EXPECT_NEAR(sim.timeS(), 0.005, 1e-12);
  EXPECT_THROW(sim.triggerCamera("m", 0, -0.001), std::invalid_argument);
  EXPECT_THROW(sim.triggerCamera("m", 0, std::nan("")), std::invalid_argument);
}

TEST(CameraPlugins, AnUntriggeredCameraIgnoresTriggersAndHasNoTriggerTopic) {
  const std::string sensor = "<sensor type='camera' name='cam'>" + cameraElement("head", "") +
                             "<plugin name='p' filename='libgazebo_ros_camera.so'/></sensor>";
  const RobotSpec spec = modelWith(sensor);
  ASSERT_EQ(spec.cameras.size(), 1u);
  EXPECT_TRUE(spec.cameras[0].trigger_topic.empty());
}

TEST(CameraPlugins, NoiseDistortionAndSixteenBitFormatsAreRead) {
  const std::string sensor =
      "<sensor type='camera' name='cam'>"
      "<camera><horizontal_fov>1.0</horizontal_fov><image><width>64</width><height>48</height>"
      "<format>R16G16B16</format></image><noise><type>gaussian</type><mean>0.01</mean>"
      "<stddev>0.007</stddev></noise><distortion><k1>-0.1</k1><k2>-0.2</k2><k3>-0.3</k3>"
      "<p1>0.01</p1><p2>0.02</p2><center>0.4 0.6</center></distortion></camera>"
      "<plugin name='p' filename='libgazebo_ros_camera.so'><autoDistortion>true"
      "</autoDistortion></plugin></sensor>";
  const RobotSpec spec = modelWith(sensor);
  ASSERT_EQ(spec.cameras.size(), 1u);
  const CameraSpec& c = spec.cameras[0];
  EXPECT_EQ(c.format, "R16G16B16");
  ASSERT_TRUE(c.noise);
  EXPECT_DOUBLE_EQ(c.noise->mean, 0.01);
  EXPECT_DOUBLE_EQ(c.noise->stddev, 0.007);
  ASSERT_TRUE(c.distortion);
  EXPECT_DOUBLE_EQ(c.distortion->center_x, 0.4);
  EXPECT_DOUBLE_EQ(c.distortion->center_y, 0.6);
  // camera_info's D is (k1, k2, t1, t2, k3)
  const std::array<double, 5> expected{-0.1, -0.2, 0.01, 0.02, -0.3};
  EXPECT_EQ(c.info_distortion, expected);
}

TEST(CameraPlugins, WithoutAutoDistortionCameraInfoTakesThePluginsCoefficients) {
  const std::string sensor =
      "<sensor type='camera' name='cam'>" +
      cameraElement("head", "<distortion><k1>-0.1</k1></distortion>") +
      "<plugin name='p' filename='libgazebo_ros_camera.so'><distortionK1>0.5</distortionK1>"
      "<distortionT2>0.25</distortionT2></plugin></sensor>";
  const RobotSpec spec = modelWith(sensor);
  const std::array<double, 5> expected{0.5, 0, 0, 0.25, 0};
  EXPECT_EQ(spec.cameras.at(0).info_distortion, expected);
  EXPECT_DOUBLE_EQ(spec.cameras.at(0).distortion->k1, -0.1);
}

TEST(CameraPlugins, BadNoiseOrFormatIsALoadErrorNamingTheElement) {
  const auto errorOf = [](const std::string& camera_inside) {
    try {
      modelWith("<sensor type='camera' name='cam'>" + cameraElement("head", camera_inside) +
                "<plugin name='p' filename='libgazebo_ros_camera.so'/></sensor>");
    } catch (const LoadError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(errorOf("<noise><type>gaussian</type><stddev>-1</stddev></noise>")
                .find("<noise> <stddev>: '-1' must be >= 0"),
            std::string::npos);
  EXPECT_NE(errorOf("<noise><type>uniform</type></noise>").find("'uniform' is not gaussian"),
            std::string::npos);
  EXPECT_NE(errorOf("<distortion><center>0.5</center></distortion>")
                .find("<center>: '0.5' is not two numbers"),
            std::string::npos);
}
