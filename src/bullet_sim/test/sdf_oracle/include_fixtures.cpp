// Fixtures of what a world brings in from elsewhere: <include>s by model://, relative and
// file:// URIs with their overrides, and plugins of worlds, models and sensors.
#include <gtest/gtest.h>

#include "generated_fixtures.h"
#include "plugin_params.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

const double q = kQuarterTurn;

std::string boxModel() {
  return sdfText("1.6", R"(<model name="box"><pose>0 0 0.5 0 0 0</pose>
  <link name="link"><inertial><mass>2</mass></inertial>
    <collision name="c"><geometry><box><size>1 1 1</size></box></geometry></collision></link>
</model>)");
}

GeneratedFixture includes() {
  // An <include>'s <pose> replaces the model's own (box_a is not raised by the file's
  // 0.5); without overrides the file's name, pose and static flag stay.
  const std::string world = R"(<world name="w">
  <include><uri>model://sun</uri></include>
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://box_model</uri><name>box_a</name>
    <pose>1 2 0 0 0 1.5707963267948966</pose><static>true</static></include>
  <include><uri>model://box_model</uri></include>
  <include><uri>parts/crate/model.sdf</uri><name>crate_rel</name><pose>3 0 0 0 0 0</pose></include>
  <include><uri>file://@DIR@/parts/cone/model.sdf</uri><name>cone_abs</name></include>
  <model name="shelf"><static>true</static><link name="board"/>
    <include><uri>model://box_model</uri><name>inner_box</name><pose>0 0 1 0 0 0</pose></include>
  </model>
</world>)";
  return {"includes.world",
          {{"includes.world", sdfText("1.6", world)},
           {"models/box_model/model.config",
            "<?xml version=\"1.0\"?>\n<model><name>box_model</name>"
            "<sdf version=\"1.6\">model.sdf</sdf></model>\n"},
           {"models/box_model/model.sdf", boxModel()},
           {"parts/crate/model.sdf",
            sdfText("1.6", R"(<model name="crate"><link name="link"><collision name="c">
  <geometry><box><size>0.4 0.4 0.4</size></box></geometry></collision></link></model>)")},
           {"parts/cone/model.sdf",
            sdfText("1.6", R"(<model name="cone"><static>true</static><pose>0 0 0.15 0 0 0</pose>
  <link name="link"><collision name="c"><geometry>
    <cylinder><radius>0.1</radius><length>0.3</length></cylinder></geometry></collision></link>
</model>)")}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfWorld& w = need(doc.world, "world");
            EXPECT_EQ(need(w.lights, "sun").type, "directional") << "the built-in sun";
            need(w.models, "ground_plane");
            const SdfModel& box_a = need(w.models, "box_a");
            expectPose(box_a.T_parent_model, sdfPose(1, 2, 0, 0, 0, q), "box_a: the include's pose");
            EXPECT_TRUE(box_a.is_static) << "box_a: the include's <static>";
            EXPECT_DOUBLE_EQ(need(box_a.links, "link").inertial.mass, 2);
            const SdfModel& box = need(w.models, "box");
            expectPose(box.T_parent_model, sdfPose(0, 0, 0.5, 0, 0, 0), "box: the file's pose");
            EXPECT_FALSE(box.is_static);
            expectPose(need(w.models, "crate_rel").T_parent_model, sdfPose(3, 0, 0, 0, 0, 0),
                       "relative URI");
            const SdfModel& cone = need(w.models, "cone_abs");
            expectPose(cone.T_parent_model, sdfPose(0, 0, 0.15, 0, 0, 0), "file:// URI");
            EXPECT_TRUE(cone.is_static);
            expectPose(need(need(w.models, "shelf").models, "inner_box").T_parent_model,
                       sdfPose(0, 0, 1, 0, 0, 0), "an include inside a model");
          }};
}

/// The parameter `path` of `plugin`, "(none)" when it has none.
std::string parameter(const SdfPlugin& plugin, const std::string& path, int nth = 1) {
  std::string problem;
  int seen = 0;
  for (const auto& [p, text] : pluginParameters(plugin.xml, &problem)) {
    if (p == path && ++seen == nth) return text;
  }
  return problem.empty() ? "(none)" : problem;
}

GeneratedFixture plugins() {
  const std::string world = R"(<world name="w">
  <plugin name="world_ticker" filename="libworld_ticker.so"><rate>5</rate>
    <ros><namespace>/sim</namespace><remapping>a:=b</remapping><remapping>c:=d</remapping></ros>
  </plugin>
  <model name="bot"><link name="chassis">
    <sensor name="cam" type="camera"><pose>0.1 0 0.2 0 0 0</pose><update_rate>30</update_rate>
      <always_on>true</always_on><visualize>true</visualize><topic>front</topic>
      <camera><horizontal_fov>1.047</horizontal_fov><image><width>320</width><height>240</height>
        </image><clip><near>0.1</near><far>100</far></clip></camera>
      <plugin name="cam_ctrl" filename="libgazebo_ros_camera.so"><cameraName>front</cameraName>
        <frameName>cam_link</frameName></plugin>
    </sensor>
    <sensor name="lidar" type="ray"><ray><scan><horizontal><samples>360</samples>
      <min_angle>0</min_angle><max_angle>6.28</max_angle></horizontal></scan>
      <range><min>0.12</min><max>3.5</max></range></ray></sensor>
  </link>
  <plugin name="drive" filename="libgazebo_ros_diff_drive.so"><wheelSeparation>0.16</wheelSeparation>
    <wheelDiameter>0.066</wheelDiameter><leftJoint>wheel_left_joint</leftJoint></plugin>
  </model>
</world>)";
  return {"plugins.world", {{"plugins.world", sdfText("1.6", world)}}, [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfWorld& w = need(doc.world, "world");
            const SdfPlugin& ticker = need(w.plugins, "world_ticker");
            EXPECT_EQ(ticker.filename, "libworld_ticker.so");
            EXPECT_EQ(parameter(ticker, "rate"), "5");
            EXPECT_EQ(parameter(ticker, "ros/namespace"), "/sim");
            EXPECT_EQ(parameter(ticker, "ros/remapping", 2), "c:=d");
            const SdfModel& bot = need(w.models, "bot");
            const SdfPlugin& drive = need(bot.plugins, "drive");
            EXPECT_EQ(drive.filename, "libgazebo_ros_diff_drive.so");
            EXPECT_EQ(parameter(drive, "wheelSeparation"), "0.16");
            EXPECT_EQ(parameter(drive, "leftJoint"), "wheel_left_joint");
            const SdfLink& chassis = need(bot.links, "chassis");
            const SdfSensor& cam = need(chassis.sensors, "cam");
            EXPECT_EQ(cam.type, "camera");
            expectPose(cam.T_link_sensor, sdfPose(0.1, 0, 0.2, 0, 0, 0), "camera");
            EXPECT_DOUBLE_EQ(cam.update_rate_hz, 30);
            EXPECT_TRUE(cam.always_on);
            EXPECT_TRUE(cam.visualize);
            EXPECT_EQ(cam.topic, "front");
            EXPECT_EQ(parameter(need(cam.plugins, "cam_ctrl"), "cameraName"), "front");
            const SdfSensor& lidar = need(chassis.sensors, "lidar");
            EXPECT_EQ(lidar.type, "ray");
            EXPECT_EQ(lidar.topic, "") << "no <topic>";
            EXPECT_EQ(lidar.update_rate_hz, 0);
            EXPECT_FALSE(lidar.always_on);
          }};
}

}  // namespace

std::vector<GeneratedFixture> featureFixtures() {
  std::vector<GeneratedFixture> out = {includes(), plugins()};
  for (GeneratedFixture& f : appearanceFixtures()) out.push_back(std::move(f));
  return out;
}

}  // namespace bullet_sim_test
