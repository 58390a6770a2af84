// Sensors and plugins of SDF models: a <sensor> in a link of a world's model (static or
// movable) or of a spawned SDF model, and a model's <plugin>s, go through the same readers
// as a URDF's <gazebo> blocks; a static model that carries them is a robot that stays put.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/errors.h"
#include "bullet_sim/simulation.h"

using namespace bullet_sim;

namespace {

const UriResolver kNoPaths{ResourcePaths{}};

std::string world(const std::string& models, const std::string& version = "1.6") {
  return "<sdf version='" + version + "'><world name='w'>" + models + "</world></sdf>";
}

/// A camera <sensor> with its ROS plugin, at `pose` in its link.
std::string cameraSensor(const std::string& name, const std::string& pose,
                         const std::string& pose_attributes = "") {
  return "<sensor type='camera' name='" + name + "'><pose" + pose_attributes + ">" + pose +
         "</pose><update_rate>10</update_rate><camera><horizontal_fov>1.0</horizontal_fov>"
         "<image><width>64</width><height>48</height></image></camera>"
         "<plugin name='p' filename='libgazebo_ros_camera.so'><cameraName>" + name +
         "</cameraName></plugin></sensor>";
}

const WorldModel* modelNamed(const WorldSpec& spec, const std::string& name) {
  for (const WorldModel& m : spec.models)
    if (m.name == name) return &m;
  return nullptr;
}

Eigen::Isometry3d isometry(const Pose3& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(p.position);
  T.rotate(p.orientation);
  return T;
}

Eigen::Isometry3d xyzRpy(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(Eigen::Vector3d(x, y, z));
  T.rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
           Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
  return T;
}

void expectNear(const Eigen::Isometry3d& expected, const Eigen::Isometry3d& actual, double tol) {
  EXPECT_TRUE(expected.matrix().isApprox(actual.matrix(), tol))
      << "expected\n" << expected.matrix() << "\nactual\n" << actual.matrix();
}

const std::string kStaticCamera =
    "<model name='camera_model'><static>true</static><pose>1 2 0.5 0 0 1.5707963267948966</pose>"
    "<link name='base'><visual name='v'><geometry><box><size>0.1 0.1 0.1</size></box>"
    "</geometry></visual></link>"
    "<link name='camera_link'><pose>0 0 0.3 0 0 0</pose>" +
    cameraSensor("cam", "0.1 0 0 0 0.5 0") + "</link></model>";

}  // namespace

TEST(SdfModelSensors, AStaticModelWithACameraIsAStaticRobotWithThatCamera) {
  const WorldSpec spec = loadWorldString(world(kStaticCamera), "w.world", kNoPaths);
  for (const StaticModel& m : spec.static_models) EXPECT_NE(m.name, "camera_model");
  const WorldModel* model = modelNamed(spec, "camera_model");
  ASSERT_NE(model, nullptr);
  EXPECT_TRUE(model->spec.is_static);
  ASSERT_EQ(model->spec.cameras.size(), 1u);
  const CameraSpec& camera = model->spec.cameras[0];
  EXPECT_EQ(camera.link, "camera_link");
  EXPECT_EQ(camera.camera_name, "cam");
  EXPECT_EQ(camera.width, 64);
  EXPECT_DOUBLE_EQ(camera.update_rate_hz, 10);
  expectNear(xyzRpy(0.1, 0, 0, 0, 0.5, 0), isometry(camera.pose_in_link), 1e-12);
}

TEST(SdfModelSensors, AStaticRobotDoesNotMoveAndItsLinksStandWhereTheModelPutsThem) {
  const WorldSpec spec = loadWorldString(
      "<sdf version='1.6'><world name='w'><include><uri>model://ground_plane</uri></include>" +
          kStaticCamera + "</world></sdf>",
      "w.world", UriResolver(ResourcePaths{}));
  Simulation sim(spec, SimConfig{});
  const Eigen::Isometry3d T_world_model = xyzRpy(1, 2, 0.5, 0, 0, M_PI / 2);
  for (int i = 0; i < 1000; ++i) sim.step();  // 1 s: a free body would fall 4.9 m
  for (const LinkPose& p : sim.linkPoses("camera_model")) {
    const Eigen::Isometry3d expected =
        p.link == "camera_link" ? T_world_model * xyzRpy(0, 0, 0.3, 0, 0, 0) : T_world_model;
    SCOPED_TRACE(p.link);
    expectNear(expected, isometry(p.pose), 1e-9);
  }
  EXPECT_EQ(sim.linkPoses("camera_model").size(), 2u);
}

TEST(SdfModelSensors, ASensorPoseRelativeToAFrameReachesTheReaderInTheLinkFrame) {
  // SDF 1.7: the sensor is posed relative to the model frame; its link sits 0.3 above it.
  const std::string model =
      "<model name='m'><static>true</static><link name='l'><pose>0 0 0.3 0 0 0</pose>" +
      cameraSensor("cam", "0 0 1 0 0 0", " relative_to='__model__'") + "</link></model>";
  const WorldSpec spec = loadWorldString(world(model, "1.7"), "w.world", kNoPaths);
  const WorldModel* m = modelNamed(spec, "m");
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->spec.cameras.size(), 1u);
  expectNear(xyzRpy(0, 0, 0.7, 0, 0, 0), isometry(m->spec.cameras[0].pose_in_link), 1e-12);
}

TEST(SdfModelSensors, ASensorLookingStraightDownKeepsItsYaw) {
  // pitch pi/2 (a camera looking down, as gazebo_ros_pkgs' distortion worlds hold theirs)
  // and yaw 0.3: the rotation passes to the reader whole.
  const std::string model = "<model name='m'><static>true</static><link name='l'>" +
                            cameraSensor("cam", "1 2 3 0 1.5707963267948966 0.3") +
                            "</link></model>";
  const WorldSpec spec = loadWorldString(world(model), "w.world", kNoPaths);
  const WorldModel* m = modelNamed(spec, "m");
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->spec.cameras.size(), 1u);
  expectNear(xyzRpy(1, 2, 3, 0, M_PI / 2, 0.3), isometry(m->spec.cameras[0].pose_in_link),
             1e-9);
}

TEST(SdfModelSensors, AMovableModelsSensorIsRead) {
  const std::string model =
      "<model name='ball'><pose>0 0 1 0 0 0</pose><link name='body'>"
      "<sensor type='ray' name='lidar'><update_rate>5</update_rate><ray><scan><horizontal>"
      "<samples>10</samples><min_angle>-1</min_angle><max_angle>1</max_angle></horizontal>"
      "</scan><range><min>0.1</min><max>5</max></range></ray>"
      "<plugin name='l' filename='libgazebo_ros_laser.so'><topicName>ball_scan</topicName>"
      "</plugin></sensor></link></model>";
  const WorldSpec spec = loadWorldString(world(model), "w.world", kNoPaths);
  const WorldModel* m = modelNamed(spec, "ball");
  ASSERT_NE(m, nullptr);
  EXPECT_FALSE(m->spec.is_static);
  ASSERT_EQ(m->spec.rays.size(), 1u);
  EXPECT_EQ(m->spec.rays[0].topic, "ball_scan");
  EXPECT_EQ(m->spec.rays[0].link, "body");
  EXPECT_EQ(m->spec.rays[0].samples, 10);
}

TEST(SdfModelSensors, ASpawnedStaticSdfModelKeepsItsSensorsAndStaysStatic) {
  const std::string sdf =
      "<sdf version='1.6'><model name='imu_box'><static>true</static><link name='l'>"
      "<sensor type='imu' name='imu'><update_rate>50</update_rate>"
      "<plugin name='i' filename='libgazebo_ros_imu_sensor.so'><topicName>box_imu</topicName>"
      "</plugin></sensor></link></model></sdf>";
  const RobotSpec spec = parseSdfModelString(sdf, "spawned", kNoPaths);
  EXPECT_TRUE(spec.is_static);
  ASSERT_EQ(spec.imus.size(), 1u);
  EXPECT_EQ(spec.imus[0].link, "l");
  EXPECT_EQ(spec.imus[0].topic, "box_imu");
}

TEST(SdfModelSensors, AModelPluginIsReadAsAUrdfOnesIs) {
  const std::string sdf =
      "<sdf version='1.6'><model name='m'><link name='l'/>"
      "<plugin name='imu' filename='libgazebo_ros_imu.so'><bodyName>l</bodyName>"
      "<topicName>model_imu</topicName><updateRate>20</updateRate></plugin></model></sdf>";
  const RobotSpec spec = parseSdfModelString(sdf, "spawned", kNoPaths);
  ASSERT_EQ(spec.imus.size(), 1u);
  EXPECT_EQ(spec.imus[0].topic, "model_imu");
  EXPECT_DOUBLE_EQ(spec.imus[0].update_rate_hz, 20);
}

TEST(SdfModelSensors, UnsupportedSensorsAndPluginsAreWarnedAboutByName) {
  const std::string sdf =
      "<sdf version='1.6'><model name='m'><link name='l'>"
      "<sensor type='altimeter' name='alt'/></link>"
      "<plugin name='x' filename='libmy_plugin.so'/></model></sdf>";
  const RobotSpec spec = parseSdfModelString(sdf, "spawned", kNoPaths);
  bool sensor_warned = false, plugin_warned = false;
  for (const std::string& w : spec.warnings) {
    sensor_warned |= w.find("sensor type 'altimeter'") != std::string::npos;
    plugin_warned |= w.find("plugin 'libmy_plugin.so'") != std::string::npos;
  }
  EXPECT_TRUE(sensor_warned);
  EXPECT_TRUE(plugin_warned);
}

TEST(SdfModelSensors, ABadSensorValueNamesTheFileModelLinkAndElement) {
  const std::string model =
      "<model name='m'><static>true</static><link name='l'>"
      "<sensor type='camera' name='cam'><camera><horizontal_fov>wide</horizontal_fov>"
      "</camera><plugin name='p' filename='libgazebo_ros_camera.so'/></sensor></link></model>";
  try {
    loadWorldString(world(model), "w.world", kNoPaths);
    FAIL() << "no LoadError";
  } catch (const LoadError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("w.world"), std::string::npos) << what;
    EXPECT_NE(what.find("model 'm' link 'l' <sensor name=\"cam\">"), std::string::npos) << what;
    EXPECT_NE(what.find("<horizontal_fov>"), std::string::npos) << what;
  }
}

TEST(SdfModelSensors, AStaticModelWithoutSensorsStaysAStaticShape) {
  const std::string model =
      "<model name='wall'><static>true</static><link name='l'><collision name='c'><geometry>"
      "<box><size>1 1 1</size></box></geometry></collision></link></model>";
  const WorldSpec spec = loadWorldString(world(model), "w.world", kNoPaths);
  EXPECT_TRUE(spec.models.empty());
  ASSERT_EQ(spec.static_models.size(), 1u);
  EXPECT_EQ(spec.static_models[0].name, "wall");
}
