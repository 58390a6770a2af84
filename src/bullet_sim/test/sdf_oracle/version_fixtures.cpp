// One fixture per difference between SDF versions, each with its key values worked out
// by hand. q is a quarter turn (kQuarterTurn); Rz(q) takes (x, y, z) to (-y, x, z).
#include <gtest/gtest.h>

#include "generated_fixtures.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

const double q = kQuarterTurn;

/// A three-link arm whose forearm and hand are yawed a quarter turn; `elbow_axis` and
/// `wrist_axis` are the joints' <axis> contents.
std::string yawedArm(const std::string& elbow_axis, const std::string& wrist_axis) {
  return R"(<model name="arm">
  <link name="base"/>
  <link name="forearm"><pose>0 0 1 0 0 1.5707963267948966</pose></link>
  <link name="hand"><pose>0 0 2 0 0 1.5707963267948966</pose></link>
  <joint name="elbow" type="revolute"><parent>base</parent><child>forearm</child>
    <axis>)" + elbow_axis + R"(</axis></joint>
  <joint name="wrist" type="revolute"><parent>forearm</parent><child>hand</child>
    <axis>)" + wrist_axis + R"(</axis></joint>
</model>)";
}

const SdfJointAxis& axisOf(const SdfModel& model, const std::string& joint) {
  return need(need(model.joints, joint).axis, "joint '" + joint + "' <axis>");
}

GeneratedFixture axis14() {
  // SDF 1.4 gives <xyz> in the model frame: the forearm's yaw does not turn it.
  return {"axis_1_4.world",
          {{"axis_1_4.world",
            sdfText("1.4", "<world name=\"w\">" + yawedArm("<xyz>1 0 0</xyz>", "<xyz>0 1 0</xyz>") +
                           "</world>")}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& arm = need(need(doc.world, "world").models, "arm");
            expectVector(axisOf(arm, "elbow").xyz_in_model, {1, 0, 0}, "1.4 elbow axis");
            expectVector(axisOf(arm, "wrist").xyz_in_model, {0, 1, 0}, "1.4 wrist axis");
            expectPose(need(arm.joints, "elbow").T_model_joint, sdfPose(0, 0, 1, 0, 0, q),
                       "1.4 elbow at its child");
          }};
}

GeneratedFixture axis15() {
  // 1.5: with use_parent_model_frame false <xyz> is in the joint frame (here the yawed
  // child's): 1 0 0 turns into 0 1 0; with it true, the model frame as in 1.4.
  return {"axis_1_5.world",
          {{"axis_1_5.world",
            sdfText("1.5", "<world name=\"w\">" +
                           yawedArm("<xyz>1 0 0</xyz>"
                                    "<use_parent_model_frame>false</use_parent_model_frame>",
                                    "<xyz>1 0 0</xyz>"
                                    "<use_parent_model_frame>true</use_parent_model_frame>") +
                           "</world>")}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& arm = need(need(doc.world, "world").models, "arm");
            expectVector(axisOf(arm, "elbow").xyz_in_model, {0, 1, 0}, "1.5 elbow, joint frame");
            expectVector(axisOf(arm, "wrist").xyz_in_model, {1, 0, 0}, "1.5 wrist, model frame");
          }};
}

GeneratedFixture axis16() {
  // 1.6, a model file: use_parent_model_frame false and true, and a joint without it
  // (false) yawed a further quarter turn on its child: the joint frame is yawed a half
  // turn, 1 0 0 -> -1 0 0.
  const std::string model = R"(<model name="arm">
  <link name="base"/>
  <link name="forearm"><pose>0 0 1 0 0 1.5707963267948966</pose></link>
  <link name="hand"><pose>0 0 2 0 0 1.5707963267948966</pose></link>
  <link name="finger"><pose>0 0 3 0 0 1.5707963267948966</pose></link>
  <joint name="elbow" type="revolute"><parent>base</parent><child>forearm</child>
    <axis><xyz>1 0 0</xyz><use_parent_model_frame>false</use_parent_model_frame></axis></joint>
  <joint name="wrist" type="revolute"><parent>forearm</parent><child>hand</child>
    <axis><xyz>1 0 0</xyz><use_parent_model_frame>true</use_parent_model_frame></axis></joint>
  <joint name="knuckle" type="revolute"><parent>hand</parent><child>finger</child>
    <pose>0 0 0 0 0 1.5707963267948966</pose><axis><xyz>1 0 0</xyz></axis></joint>
</model>)";
  return {"axis_1_6.sdf", {{"axis_1_6.sdf", sdfText("1.6", model)}}, [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& arm = need(doc.model, "the document's model");
            expectVector(axisOf(arm, "elbow").xyz_in_model, {0, 1, 0}, "1.6 elbow");
            expectVector(axisOf(arm, "wrist").xyz_in_model, {1, 0, 0}, "1.6 wrist");
            expectVector(axisOf(arm, "knuckle").xyz_in_model, {-1, 0, 0}, "1.6 knuckle");
            expectPose(need(arm.joints, "knuckle").T_model_joint,
                       sdfPose(0, 0, 3, 0, 0, 2 * q), "1.6 knuckle on its yawed child");
          }};
}

GeneratedFixture poseFrame16() {
  // 1.6 <pose frame="a">: b is 2 m along a's x, which is the model's y: (1, 2, 0).
  // frame='' (as Gazebo writes it) is the default frame.
  const std::string world = R"(<world name="w"><model name="m">
  <link name="a"><pose>1 0 0 0 0 1.5707963267948966</pose></link>
  <link name="b"><pose frame="a">2 0 0 0 0 0</pose></link>
  <link name="c"><pose frame=''>0 0 3 0 0 0</pose></link>
</model></world>)";
  return {"pose_frame_1_6.world", {{"pose_frame_1_6.world", sdfText("1.6", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& m = need(need(doc.world, "world").models, "m");
            expectPose(need(m.links, "b").T_model_link, sdfPose(1, 2, 0, 0, 0, q), "b in a");
            expectPose(need(m.links, "c").T_model_link, sdfPose(0, 0, 3, 0, 0, 0), "c, frame ''");
          }};
}

GeneratedFixture gravity15() {
  // 1.5 keeps <gravity> inside <physics>; 1.6 moved it up to <world>.
  const std::string world = R"(<world name="mars">
  <physics type="ode"><gravity>0 0 -3.711</gravity><max_step_size>0.004</max_step_size>
    <real_time_factor>2</real_time_factor><real_time_update_rate>250</real_time_update_rate>
  </physics>
  <model name="rock"><static>true</static><link name="link"><collision name="c">
    <geometry><sphere><radius>0.5</radius></sphere></geometry></collision></link></model>
</world>)";
  return {"gravity_1_5.world", {{"gravity_1_5.world", sdfText("1.5", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfWorld& w = need(doc.world, "world");
            expectVector(w.gravity, {0, 0, -3.711}, "gravity from <physics>");
            EXPECT_DOUBLE_EQ(w.max_step_size_s, 0.004);
            EXPECT_DOUBLE_EQ(w.real_time_factor, 2);
            EXPECT_DOUBLE_EQ(w.real_time_update_rate_hz, 250);
          }};
}

GeneratedFixture relativeTo17() {
  // A at (1, 0, 0) yawed q; B 2 m along A's x: (1, 2, 0) yawed q. J 1 m along A's y:
  // (1, 0, 0) + (-1, 0, 0). K 0.5 m above its child C. N 1 m above A. A's visual sits on
  // B: 2 m along A's x. B's collision on the model frame: the inverse of B's pose,
  // (-2, 1, 0) yawed -q.
  const std::string world = R"(<world name="w"><model name="m"><pose>10 0 0 0 0 0</pose>
  <link name="A"><pose>1 0 0 0 0 1.5707963267948966</pose>
    <visual name="v"><pose relative_to="B">0 0 0 0 0 0</pose>
      <geometry><box><size>1 1 1</size></box></geometry></visual></link>
  <link name="B"><pose relative_to="A">2 0 0 0 0 0</pose>
    <collision name="c"><pose relative_to="__model__">0 0 0 0 0 0</pose>
      <geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link>
  <link name="C"><pose>0 0 1 0 0 0</pose></link>
  <joint name="J" type="revolute"><pose relative_to="A">0 1 0 0 0 0</pose>
    <parent>A</parent><child>B</child><axis><xyz>0 0 1</xyz></axis></joint>
  <joint name="K" type="fixed"><pose>0 0 0.5 0 0 0</pose><parent>B</parent><child>C</child></joint>
  <model name="N"><pose relative_to="A">0 0 1 0 0 0</pose><link name="n"/></model>
</model></world>)";
  return {"relative_to_1_7.world", {{"relative_to_1_7.world", sdfText("1.7", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& m = need(need(doc.world, "world").models, "m");
            expectPose(m.T_parent_model, sdfPose(10, 0, 0, 0, 0, 0), "m in the world");
            expectPose(need(m.links, "B").T_model_link, sdfPose(1, 2, 0, 0, 0, q), "B");
            expectPose(need(need(m.links, "A").visuals, "v").T_link_visual,
                       sdfPose(2, 0, 0, 0, 0, 0), "A's visual on B");
            expectPose(need(need(m.links, "B").collisions, "c").T_link_collision,
                       sdfPose(-2, 1, 0, 0, 0, -q), "B's collision on the model");
            expectPose(need(m.joints, "J").T_model_joint, sdfPose(0, 0, 0, 0, 0, q), "J");
            expectPose(need(m.joints, "K").T_model_joint, sdfPose(0, 0, 1.5, 0, 0, 0), "K");
            expectPose(need(m.models, "N").T_parent_model, sdfPose(1, 0, 1, 0, 0, q), "N");
          }};
}

GeneratedFixture frames17() {
  // wf at (0, 5, 0) yawed q: lamp 3 m above it, x 1 m along its x: (0, 6, 0).
  // F1 1 m above A, F2 1 m along F1's x (the model's y): D = A * (1, 0, 1) = (1, 1, 1)
  // yawed q. F3 is posed on the model (attached_to only says which link carries it).
  const std::string world = R"(<world name="w">
  <frame name="wf"><pose>0 5 0 0 0 1.5707963267948966</pose></frame>
  <light name="lamp" type="point"><pose relative_to="wf">0 0 3 0 0 0</pose></light>
  <model name="x"><pose relative_to="wf">1 0 0 0 0 0</pose><link name="l"/></model>
  <model name="m">
    <link name="A"><pose>1 0 0 0 0 1.5707963267948966</pose></link>
    <frame name="F1" attached_to="A"><pose>0 0 1 0 0 0</pose></frame>
    <frame name="F2" attached_to="F1"><pose>1 0 0 0 0 0</pose></frame>
    <frame name="F3" attached_to="F2"><pose relative_to="__model__">5 0 0 0 0 0</pose></frame>
    <link name="D"><pose relative_to="F2">0 0 0 0 0 0</pose></link>
    <link name="E"><pose relative_to="F3">0 1 0 0 0 0</pose></link>
    <joint name="J" type="fixed"><pose relative_to="F1">0 0 0 0 0 0</pose>
      <parent>A</parent><child>D</child></joint>
  </model>
</world>)";
  return {"frames_1_7.world", {{"frames_1_7.world", sdfText("1.7", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfWorld& w = need(doc.world, "world");
            expectPose(need(w.lights, "lamp").T_world_light, sdfPose(0, 5, 3, 0, 0, q), "lamp");
            expectPose(need(w.models, "x").T_parent_model, sdfPose(0, 6, 0, 0, 0, q), "x");
            const SdfModel& m = need(w.models, "m");
            expectPose(need(m.links, "D").T_model_link, sdfPose(1, 1, 1, 0, 0, q), "D on F2");
            expectPose(need(m.links, "E").T_model_link, sdfPose(5, 1, 0, 0, 0, 0), "E on F3");
            expectPose(need(m.joints, "J").T_model_joint, sdfPose(1, 0, 1, 0, 0, q), "J on F1");
          }};
}

}  // namespace

std::vector<GeneratedFixture> versionFixtures() {
  std::vector<GeneratedFixture> out = {axis14(), axis15(),      axis16(),  poseFrame16(),
                                       gravity15(), relativeTo17(), frames17()};
  for (GeneratedFixture& f : modelScopeFixtures()) out.push_back(std::move(f));
  return out;
}

}  // namespace bullet_sim_test
