// The SDF reader against values worked out by hand from the SDF spec (1.4 to 1.9) and
// Gazebo classic's reading of it: each version difference that changes meaning, frames,
// includes, the defaults of absent elements, and errors that name the file, line and
// element. These run where libsdformat is not installed (Debian 13); the differential test
// (test/sdf_oracle) compares the reader with libsdformat where it is.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "description/sdf/sdf_reader.h"
#include "load_errors.h"
#include "temp_dir.h"

using namespace bullet_sim;
using bullet_sim_test::loadErrorOf;
using bullet_sim_test::TempDir;

namespace {

const UriResolver kNoPaths{ResourcePaths{}};

struct Read {
  SdfDocument doc;
  std::vector<std::string> warnings;
};

Read read(const std::string& text, const std::string& source = "t.sdf",
          const UriResolver& resolver = kNoPaths, const std::string& path = "") {
  Read out;
  const auto xml = parseSdfXml(text, source, "world");
  out.doc = readSdf(*xml, source, path, resolver, &out.warnings);
  return out;
}

/// A model whose joint `j` (axis 1 0 0, pose 0) joins link `a` to link `b`, which is yawed
/// by 90 degrees: in b's frame (the joint's) x is the model's y.
std::string yawedChildModel(const std::string& version, const std::string& axis_extra) {
  return "<sdf version='" + version + "'><model name='m'>"
         "<link name='a'/><link name='b'><pose>1 0 0 0 0 1.5707963267948966</pose></link>"
         "<joint name='j' type='revolute'><parent>a</parent><child>b</child>"
         "<axis><xyz>1 0 0</xyz>" + axis_extra + "</axis></joint></model></sdf>";
}

Eigen::Vector3d axisOf(const Read& r) { return r.doc.model->joints.at(0).axis->xyz_in_model; }

}  // namespace

TEST(SdfVersions, Sdf14JointAxisIsInTheModelFrame) {
  EXPECT_TRUE(axisOf(read(yawedChildModel("1.4", ""))).isApprox(Eigen::Vector3d(1, 0, 0), 1e-9));
}

TEST(SdfVersions, Sdf15JointAxisIsInTheJointFrameUnlessUseParentModelFrame) {
  EXPECT_TRUE(axisOf(read(yawedChildModel("1.5", ""))).isApprox(Eigen::Vector3d(0, 1, 0), 1e-9));
  EXPECT_TRUE(axisOf(read(yawedChildModel("1.6", "<use_parent_model_frame>true"
                                                 "</use_parent_model_frame>")))
                  .isApprox(Eigen::Vector3d(1, 0, 0), 1e-9));
}

TEST(SdfVersions, Sdf17ExpressedInNamesTheFrame) {
  const std::string m = "<sdf version='1.7'><model name='m'>"
                        "<link name='a'/><link name='b'><pose>1 0 0 0 0 1.5707963267948966</pose>"
                        "</link><frame name='f'><pose>0 0 0 1.5707963267948966 0 0</pose></frame>"
                        "<joint name='j' type='revolute'><parent>a</parent><child>b</child>"
                        "<axis><xyz expressed_in='X'>0 1 0</xyz></axis></joint></model></sdf>";
  auto with = [&](const std::string& frame) {
    std::string text = m;
    text.replace(text.find("'X'"), 3, "'" + frame + "'");
    return axisOf(read(text));
  };
  EXPECT_TRUE(with("__model__").isApprox(Eigen::Vector3d(0, 1, 0), 1e-9));
  EXPECT_TRUE(with("f").isApprox(Eigen::Vector3d(0, 0, 1), 1e-9));  // f rolled 90 deg
  EXPECT_TRUE(with("").isApprox(Eigen::Vector3d(-1, 0, 0), 1e-9));  // the joint (b) frame
}

TEST(SdfVersions, Sdf16PoseFrameIsRelativeTo) {
  const Read r = read("<sdf version='1.6'><model name='m'>"
                      "<link name='a'><pose>1 0 0 0 0 1.5707963267948966</pose></link>"
                      "<link name='b'><pose frame='a'>2 0 0 0 0 0</pose></link></model></sdf>");
  // 2 m along a's x, which is the model's y, from a at (1, 0, 0).
  EXPECT_TRUE(r.doc.model->links.at(1).T_model_link.translation().isApprox(
      Eigen::Vector3d(1, 2, 0), 1e-9));
}

TEST(SdfVersions, GravityMovedFromPhysicsToWorldIn16) {
  const std::string physics = "<physics type='ode'><gravity>0 0 -3</gravity></physics>";
  EXPECT_DOUBLE_EQ(read("<sdf version='1.5'><world name='w'>" + physics + "</world></sdf>")
                       .doc.world->gravity.z(), -3);
  EXPECT_DOUBLE_EQ(read("<sdf version='1.6'><world name='w'>" + physics + "</world></sdf>")
                       .doc.world->gravity.z(), -9.8);
}

TEST(SdfFrames, JointPoseIsInTheChildLinkFrameAndFramesChain) {
  const Read r = read(
      "<sdf version='1.7'><model name='m'><link name='a'/>"
      "<link name='b'><pose relative_to='f2'>0 0 1 0 0 0</pose></link>"
      "<frame name='f1' attached_to='a'><pose>1 0 0 0 0 0</pose></frame>"
      "<frame name='f2' attached_to='f1'><pose>0 1 0 0 0 0</pose></frame>"
      "<joint name='j' type='fixed'><pose>0 0 0.5 0 0 0</pose><parent>a</parent><child>b</child>"
      "</joint></model></sdf>");
  const SdfModel& m = *r.doc.model;
  EXPECT_TRUE(m.links.at(1).T_model_link.translation().isApprox(Eigen::Vector3d(1, 1, 1), 1e-9));
  EXPECT_TRUE(m.joints.at(0).T_model_joint.translation().isApprox(Eigen::Vector3d(1, 1, 1.5), 1e-9));
}

TEST(SdfFrames, ACycleNamesTheFramesAndTheLine) {
  const std::string error = loadErrorOf([] {
    read("<sdf version='1.7'><model name='m'>\n<link name='a'>"
         "<pose relative_to='b'/></link>\n<link name='b'><pose relative_to='a'/></link>"
         "</model></sdf>");
  });
  EXPECT_NE(error.find("t.sdf:"), std::string::npos) << error;
  EXPECT_NE(error.find("the poses of frames a, b are relative to each other in a cycle"),
            std::string::npos) << error;
}

TEST(SdfFrames, AnUnknownFrameIsAnError) {
  EXPECT_EQ(loadErrorOf([] {
              read("<sdf version='1.7'><model name='m'>\n<link name='a'>"
                   "<pose relative_to='nowhere'>0 0 0 0 0 0</pose></link></model></sdf>");
            }),
            "t.sdf:2: <model name=\"m\"> <link name=\"a\">: pose relative_to/frame 'nowhere' "
            "names no frame of model 'm'");
}

TEST(SdfDefaults, AbsentElementsTakeTheSpecsDefaults) {
  const Read r = read("<sdf version='1.6'><world name='w'><light name='l'/><model name='m'>"
                      "<link name='a'><collision name='c'><geometry><box/></geometry></collision>"
                      "</link><joint name='j' type='revolute'><parent>world</parent>"
                      "<child>a</child><axis/></joint></model></world></sdf>");
  const SdfWorld& w = *r.doc.world;
  EXPECT_EQ(w.max_step_size_s, 0.001);
  EXPECT_TRUE(w.ambient.isApprox(Eigen::Vector4f(0.4f, 0.4f, 0.4f, 1)));
  const SdfLight& l = w.lights.at(0);
  EXPECT_EQ(l.type, "point");
  EXPECT_EQ(l.range_m, 10);
  EXPECT_EQ(l.linear, 1);
  EXPECT_TRUE(l.direction.isApprox(Eigen::Vector3d(0, 0, -1)));
  const SdfLink& a = w.models.at(0).links.at(0);
  EXPECT_EQ(a.inertial.mass, 1);
  EXPECT_EQ(a.inertial.ixx, 1);
  EXPECT_TRUE(a.collisions.at(0).geometry.shape->size.isApprox(Eigen::Vector3d::Ones()));
  const SdfJointAxis& axis = *w.models.at(0).joints.at(0).axis;
  EXPECT_EQ(axis.lower, -1e16);
  EXPECT_EQ(axis.effort, -1);
  EXPECT_TRUE(axis.xyz_in_model.isApprox(Eigen::Vector3d::UnitZ()));
}

TEST(SdfMaterials, ScriptShorthandIsReadAsGazeboReadsIt) {
  // sdformat 9 gives the <script> its default <name> "__default__", which Gazebo's
  // Visual::SetMaterial ignores: the visual keeps the colours it has.
  const Read r = read("<sdf version='1.4'><model name='m'><link name='a'><visual name='v'>\n"
                      "<material><script>Gazebo/Green</script><ambient>0 0 1 1</ambient>"
                      "</material></visual></link></model></sdf>");
  const SdfMaterial& m = *r.doc.model->links.at(0).visuals.at(0).material;
  EXPECT_EQ(m.script_name, "");
  EXPECT_TRUE(m.ambient->isApprox(Eigen::Vector4f(0, 0, 1, 1)));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("t.sdf:2: <model name=\"m\"> <link name=\"a\"> <visual name=\"v\"> "
                               "<material> <script>: 'Gazebo/Green' names no material"),
            std::string::npos) << r.warnings[0];
}

TEST(SdfIncludes, OverridesAndTheBuiltInSun) {
  TempDir dir;
  dir.write("models/crate/model.config",
            "<model><sdf version='1.5'>model.sdf</sdf></model>");
  dir.write("models/crate/model.sdf",
            "<sdf version='1.5'><model name='crate'><pose>9 9 9 0 0 0</pose><link name='l'>"
            "<pose>0 0 0.5 0 0 0</pose></link></model></sdf>");
  const Read r = read("<sdf version='1.6'><world name='w'><include><uri>model://sun</uri></include>"
                      "<include><uri>model://crate</uri><name>c2</name><static>true</static>"
                      "<pose>1 2 0 0 0 0</pose></include></world></sdf>",
                      "w.world", UriResolver(ResourcePaths{{dir.sub("models")}, {}}));
  const SdfWorld& w = *r.doc.world;
  ASSERT_EQ(w.lights.size(), 1u);
  EXPECT_EQ(w.lights[0].type, "directional");
  ASSERT_EQ(w.models.size(), 1u);
  EXPECT_EQ(w.models[0].name, "c2");
  EXPECT_TRUE(w.models[0].is_static);
  EXPECT_TRUE(w.models[0].T_parent_model.translation().isApprox(Eigen::Vector3d(1, 2, 0)));
  EXPECT_TRUE(w.models[0].links[0].T_model_link.translation().isApprox(Eigen::Vector3d(0, 0, 0.5)));
}

TEST(SdfErrors, AMalformedNumberNamesFileLineAndElement) {
  EXPECT_EQ(loadErrorOf([] {
              read("<sdf version='1.6'><model name='m'>\n<link name='a'><collision name='c'>"
                   "<geometry>\n<sphere><radius>wide</radius></sphere></geometry></collision>"
                   "</link></model></sdf>");
            }),
            "t.sdf:3: <model name=\"m\"> <link name=\"a\"> <collision name=\"c\"> <geometry> "
            "<sphere> <radius>: 'wide' is not a number");
}

TEST(SdfErrors, AJointOfAnUnknownTypeOrLink) {
  const std::string joint = "<sdf version='1.6'><model name='m'><link name='a'/><link name='b'/>"
                            "<joint name='j' type='T'><parent>a</parent><child>C</child></joint>"
                            "</model></sdf>";
  auto with = [&](const std::string& type, const std::string& child) {
    std::string text = joint;
    text.replace(text.find("'T'"), 3, "'" + type + "'");
    text.replace(text.find(">C<"), 3, ">" + child + "<");
    return loadErrorOf([&] { read(text); });
  };
  EXPECT_NE(with("hinge", "b").find("type 'hinge' is not a joint type of SDF"), std::string::npos);
  EXPECT_NE(with("revolute", "c").find("<joint name=\"j\">: 'c' names no link of the model"),
            std::string::npos);
}
