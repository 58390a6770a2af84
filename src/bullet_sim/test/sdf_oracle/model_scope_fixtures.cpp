// Fixtures of what a model's scope holds in SDF 1.7 and 1.8: axes expressed in named
// frames, the canonical link, nested models with joints between them. Key values worked
// out by hand; q is a quarter turn, Rz(q) takes (x, y, z) to (-y, x, z).
#include <gtest/gtest.h>

#include "generated_fixtures.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

const double q = kQuarterTurn;

const SdfJointAxis& axisOf(const SdfModel& model, const std::string& joint) {
  return need(need(model.joints, joint).axis, "joint '" + joint + "' <axis>");
}

GeneratedFixture expressedIn17() {
  // B, C, D are yawed -q (x -> -y), A is yawed +q (x -> y). A plain <xyz> is in the joint
  // frame (the child's here): 1 0 0 -> 0 -1 0; expressed in __model__ it stays; in A it
  // is A's x, the model's y. <xyz>0 0 2</xyz> is a direction: the unit vector 0 0 1.
  // The model's own pose is kept as written (a model file has no parent to resolve in).
  const std::string model = R"(<model name="m"><pose>0 0 0.5 0 0 0</pose>
  <link name="base"/>
  <link name="A"><pose>0 0 1 0 0 1.5707963267948966</pose></link>
  <link name="B"><pose>0 0 2 0 0 -1.5707963267948966</pose></link>
  <link name="C"><pose>0 0 3 0 0 -1.5707963267948966</pose></link>
  <link name="D"><pose>0 0 4 0 0 -1.5707963267948966</pose></link>
  <link name="E"><pose>0 0 5 0 0 0</pose></link>
  <joint name="j_fixed" type="fixed"><parent>base</parent><child>A</child></joint>
  <joint name="j_plain" type="revolute"><parent>base</parent><child>B</child>
    <axis><xyz>1 0 0</xyz></axis></joint>
  <joint name="j_model" type="revolute"><parent>base</parent><child>C</child>
    <axis><xyz expressed_in="__model__">1 0 0</xyz></axis></joint>
  <joint name="j_link" type="revolute"><parent>base</parent><child>D</child>
    <axis><xyz expressed_in="A">1 0 0</xyz></axis></joint>
  <joint name="j_slide" type="prismatic"><parent>base</parent><child>E</child>
    <axis><xyz>0 0 2</xyz>
      <limit><lower>-0.5</lower><upper>0.25</upper><effort>10</effort><velocity>0.3</velocity></limit>
      <dynamics><damping>0.7</damping><friction>0.2</friction>
        <spring_reference>0.1</spring_reference><spring_stiffness>30</spring_stiffness></dynamics>
    </axis></joint>
</model>)";
  return {"expressed_in_1_7.sdf", {{"expressed_in_1_7.sdf", sdfText("1.7", model)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& m = need(doc.model, "the document's model");
            expectPose(m.T_parent_model, sdfPose(0, 0, 0.5, 0, 0, 0), "the model's own pose");
            EXPECT_FALSE(need(m.joints, "j_fixed").axis) << "a fixed joint has no axis";
            expectVector(axisOf(m, "j_plain").xyz_in_model, {0, -1, 0}, "plain xyz");
            expectVector(axisOf(m, "j_model").xyz_in_model, {1, 0, 0}, "expressed in __model__");
            expectVector(axisOf(m, "j_link").xyz_in_model, {0, 1, 0}, "expressed in A");
            const SdfJointAxis& slide = axisOf(m, "j_slide");
            expectVector(slide.xyz_in_model, {0, 0, 1}, "0 0 2 as a unit vector");
            EXPECT_DOUBLE_EQ(slide.lower, -0.5);
            EXPECT_DOUBLE_EQ(slide.upper, 0.25);
            EXPECT_DOUBLE_EQ(slide.effort, 10);
            EXPECT_DOUBLE_EQ(slide.velocity, 0.3);
            EXPECT_DOUBLE_EQ(slide.damping, 0.7);
            EXPECT_DOUBLE_EQ(slide.friction, 0.2);
            EXPECT_DOUBLE_EQ(slide.spring_reference, 0.1);
            EXPECT_DOUBLE_EQ(slide.spring_stiffness, 30);
            const SdfJointAxis& plain = axisOf(m, "j_plain");
            EXPECT_EQ(plain.lower, -1e16) << "the spec's default limits";
            EXPECT_EQ(plain.upper, 1e16);
            EXPECT_EQ(plain.effort, -1);
            EXPECT_EQ(plain.velocity, -1);
          }};
}

GeneratedFixture canonical18() {
  // m1 names its canonical link; m2 takes its first link; m3 has none of its own and
  // takes inner's (0 2 0 + 0 0 1); m4 names a nested one: inner at (3, 0, 0) yawed q,
  // l 1 m along inner's x (the model's y): (3, 1, 0) yawed q.
  const std::string world = R"(<world name="w">
  <model name="m1" canonical_link="second"><link name="first"/>
    <link name="second"><pose>1 0 0 0 0 0</pose></link></model>
  <model name="m2"><link name="a"><pose>0 0 1 0 0 0</pose></link><link name="b"/></model>
  <model name="m3"><model name="inner"><pose>0 2 0 0 0 0</pose>
    <link name="l"><pose>0 0 1 0 0 0</pose></link></model></model>
  <model name="m4" canonical_link="inner::l"><link name="own"/>
    <model name="inner"><pose>3 0 0 0 0 1.5707963267948966</pose>
      <link name="l"><pose>1 0 0 0 0 0</pose></link></model></model>
</world>)";
  return {"canonical_1_8.world", {{"canonical_1_8.world", sdfText("1.8", world)}},
          [](const SdfDocument& doc, const CanonicalOf& canonical_of) {
            const SdfWorld& w = need(doc.world, "world");
            const auto expectCanonical = [&](const std::string& model, const std::string& link,
                                             const Eigen::Isometry3d& T) {
              const auto c =
                  canonical_of(modelFieldPath("world", model), need(w.models, model));
              const auto& picked = need(c, "model '" + model + "' canonical link");
              EXPECT_EQ(picked.first, link) << model;
              expectPose(picked.second, T, model + "'s canonical link");
            };
            EXPECT_EQ(need(w.models, "m1").canonical_link, "second");
            EXPECT_EQ(need(w.models, "m2").canonical_link, "");
            expectCanonical("m1", "second", sdfPose(1, 0, 0, 0, 0, 0));
            expectCanonical("m2", "a", sdfPose(0, 0, 1, 0, 0, 0));
            expectCanonical("m3", "inner::l", sdfPose(0, 2, 1, 0, 0, 0));
            expectCanonical("m4", "inner::l", sdfPose(3, 1, 0, 0, 0, q));
          }};
}

GeneratedFixture nestedJoints17() {
  // arm 1 m along outer's x; l 1 m above arm; tip 2 m above arm, yawed q. inner_j is at
  // tip (the arm's frame), its axis 0 1 0 in tip's frame is -1 0 0 in the arm's.
  // shoulder joins outer's base to arm::l, at that link: (1, 0, 1) in outer.
  const std::string world = R"(<world name="w"><model name="outer">
  <link name="base"/>
  <model name="arm"><pose>1 0 0 0 0 0</pose>
    <link name="l"><pose>0 0 1 0 0 0</pose></link>
    <link name="tip"><pose>0 0 2 0 0 1.5707963267948966</pose></link>
    <joint name="inner_j" type="revolute"><parent>l</parent><child>tip</child>
      <axis><xyz>0 1 0</xyz></axis></joint>
  </model>
  <joint name="shoulder" type="revolute"><parent>base</parent><child>arm::l</child>
    <axis><xyz expressed_in="__model__">0 1 0</xyz></axis></joint>
  <joint name="anchor" type="fixed"><parent>world</parent><child>base</child></joint>
</model></world>)";
  return {"nested_joints_1_7.world", {{"nested_joints_1_7.world", sdfText("1.7", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& outer = need(need(doc.world, "world").models, "outer");
            const SdfModel& arm = need(outer.models, "arm");
            expectPose(arm.T_parent_model, sdfPose(1, 0, 0, 0, 0, 0), "arm in outer");
            expectPose(need(arm.joints, "inner_j").T_model_joint, sdfPose(0, 0, 2, 0, 0, q),
                       "inner_j in arm");
            expectVector(axisOf(arm, "inner_j").xyz_in_model, {-1, 0, 0}, "inner_j axis");
            const SdfJoint& shoulder = need(outer.joints, "shoulder");
            EXPECT_EQ(shoulder.child, "arm::l");
            expectPose(shoulder.T_model_joint, sdfPose(1, 0, 1, 0, 0, 0), "shoulder in outer");
            expectVector(axisOf(outer, "shoulder").xyz_in_model, {0, 1, 0}, "shoulder axis");
            EXPECT_EQ(need(outer.joints, "anchor").parent, "world");
          }};
}

}  // namespace

std::vector<GeneratedFixture> modelScopeFixtures() {
  return {expressedIn17(), canonical18(), nestedJoints17()};
}

}  // namespace bullet_sim_test
