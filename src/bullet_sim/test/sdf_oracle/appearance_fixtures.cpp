// Fixtures of what a world looks like and is made of: lights, materials, link properties
// and inertials, geometries; each value set in the file asserted, and the spec's default
// where the file is silent (SDF 1.6's light.sdf, material.sdf, link.sdf, geometry).
#include <cmath>

#include <gtest/gtest.h>

#include "generated_fixtures.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

void expectColour(const std::optional<Eigen::Vector4f>& colour, const Eigen::Vector4f& expected,
                  const std::string& what) {
  EXPECT_LE((need(colour, what) - expected).cwiseAbs().maxCoeff(), 1e-6) << what;
}

GeneratedFixture lights() {
  const std::string world = R"(<world name="w">
  <light name="bulb" type="point"><pose>1 2 3 0 0 0</pose><diffuse>0.9 0.8 0.7 1</diffuse>
    <specular>0.2 0.2 0.2 1</specular><cast_shadows>false</cast_shadows>
    <attenuation><range>20</range><constant>0.5</constant><linear>0.01</linear>
      <quadratic>0.001</quadratic></attenuation></light>
  <light name="sunlight" type="directional"><pose>0 0 10 0 0 0</pose>
    <direction>0.5 0.1 -0.9</direction><cast_shadows>true</cast_shadows></light>
  <light name="torch" type="spot"><pose>0 0 2 0 0.5 0</pose><direction>0 0 -1</direction>
    <spot><inner_angle>0.1</inner_angle><outer_angle>0.5</outer_angle><falloff>1.2</falloff></spot>
    <attenuation><range>8</range><linear>0.2</linear></attenuation></light>
  <light name="plain" type="point"/>
</world>)";
  return {"lights.world", {{"lights.world", sdfText("1.6", world)}}, [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfWorld& w = need(doc.world, "world");
            const SdfLight& bulb = need(w.lights, "bulb");
            EXPECT_EQ(bulb.type, "point");
            expectPose(bulb.T_world_light, sdfPose(1, 2, 3, 0, 0, 0), "bulb");
            EXPECT_LE((bulb.diffuse - Eigen::Vector4f(0.9f, 0.8f, 0.7f, 1)).norm(), 1e-6);
            EXPECT_DOUBLE_EQ(bulb.range_m, 20);
            EXPECT_DOUBLE_EQ(bulb.constant, 0.5);
            EXPECT_DOUBLE_EQ(bulb.linear, 0.01);
            EXPECT_DOUBLE_EQ(bulb.quadratic, 0.001);
            const SdfLight& sun = need(w.lights, "sunlight");
            EXPECT_EQ(sun.type, "directional");
            expectVector(sun.direction, {0.5, 0.1, -0.9}, "sunlight direction");
            EXPECT_TRUE(sun.cast_shadows);
            const SdfLight& torch = need(w.lights, "torch");
            EXPECT_EQ(torch.type, "spot");
            expectPose(torch.T_world_light, sdfPose(0, 0, 2, 0, 0.5, 0), "torch");
            EXPECT_DOUBLE_EQ(torch.spot_inner_rad, 0.1);
            EXPECT_DOUBLE_EQ(torch.spot_outer_rad, 0.5);
            EXPECT_DOUBLE_EQ(torch.spot_falloff, 1.2);
            EXPECT_DOUBLE_EQ(torch.range_m, 8);
            EXPECT_DOUBLE_EQ(torch.linear, 0.2);
            EXPECT_DOUBLE_EQ(torch.constant, 1) << "<constant> left out: the spec's 1";
            const SdfLight& plain = need(w.lights, "plain");
            EXPECT_LE((plain.diffuse - Eigen::Vector4f(1, 1, 1, 1)).norm(), 1e-6);
            EXPECT_LE((plain.specular - Eigen::Vector4f(0.1f, 0.1f, 0.1f, 1)).norm(), 1e-6);
            EXPECT_DOUBLE_EQ(plain.range_m, 10);
            EXPECT_DOUBLE_EQ(plain.constant, 1);
            EXPECT_DOUBLE_EQ(plain.linear, 1);
            EXPECT_DOUBLE_EQ(plain.quadratic, 0);
            EXPECT_FALSE(plain.cast_shadows);
          }};
}

GeneratedFixture materials() {
  const std::string world = R"(<world name="w"><model name="painted"><static>true</static>
  <link name="link">
    <visual name="v_diffuse"><geometry><sphere><radius>1</radius></sphere></geometry>
      <material><diffuse>1 0 0 1</diffuse></material></visual>
    <visual name="v_script"><geometry><sphere><radius>1</radius></sphere></geometry>
      <material><script><uri>file://media/materials/scripts/gazebo.material</uri>
        <name>Gazebo/Wood</name></script><ambient>0.1 0.2 0.3 1</ambient></material></visual>
    <visual name="v_two_uris"><geometry><sphere><radius>1</radius></sphere></geometry>
      <material><script><uri>model://x/materials/scripts</uri><uri>model://x/materials/textures</uri>
        <name>X/Y</name></script></material></visual>
    <visual name="v_empty"><geometry><sphere><radius>1</radius></sphere></geometry>
      <material/></visual>
    <visual name="v_none"><transparency>0.25</transparency><cast_shadows>false</cast_shadows>
      <geometry><sphere><radius>1</radius></sphere></geometry></visual>
    <visual name="v_unlit"><geometry><sphere><radius>1</radius></sphere></geometry>
      <material><lighting>false</lighting><emissive>0 1 0 1</emissive>
        <specular>0.5 0.5 0.5 1</specular></material></visual>
  </link></model></world>)";
  return {"materials.world", {{"materials.world", sdfText("1.6", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfLink& link = need(need(need(doc.world, "world").models, "painted").links,
                                       "link");
            const auto material = [&](const std::string& visual) -> const SdfMaterial& {
              return need(need(link.visuals, visual).material, visual + " <material>");
            };
            const SdfMaterial& diffuse = material("v_diffuse");
            expectColour(diffuse.diffuse, {1, 0, 0, 1}, "v_diffuse diffuse");
            EXPECT_FALSE(diffuse.ambient || diffuse.specular || diffuse.emissive)
                << "only the colours the file gives";
            EXPECT_EQ(diffuse.script_name, "");
            const SdfMaterial& script = material("v_script");
            EXPECT_EQ(script.script_name, "Gazebo/Wood");
            EXPECT_EQ(script.script_uris,
                      std::vector<std::string>{"file://media/materials/scripts/gazebo.material"});
            expectColour(script.ambient, {0.1f, 0.2f, 0.3f, 1}, "v_script ambient");
            EXPECT_EQ(material("v_two_uris").script_uris.size(), 2u);
            const SdfMaterial& empty = material("v_empty");
            EXPECT_FALSE(empty.ambient || empty.diffuse || empty.specular || empty.emissive);
            EXPECT_TRUE(empty.lighting);
            const SdfVisual& none = need(link.visuals, "v_none");
            EXPECT_FALSE(none.material);
            EXPECT_DOUBLE_EQ(none.transparency, 0.25);
            EXPECT_FALSE(none.cast_shadows);
            const SdfMaterial& unlit = material("v_unlit");
            EXPECT_FALSE(unlit.lighting);
            expectColour(unlit.emissive, {0, 1, 0, 1}, "v_unlit emissive");
          }};
}

GeneratedFixture linkProperties() {
  const std::string world = R"(<world name="w"><model name="cart">
  <link name="body"><gravity>false</gravity><kinematic>true</kinematic><self_collide>true</self_collide>
    <inertial><pose>0.1 0 0.05 0 0 0</pose><mass>3.5</mass><inertia><ixx>0.2</ixx><ixy>0.01</ixy>
      <ixz>0.02</ixz><iyy>0.25</iyy><iyz>0.03</iyz><izz>0.3</izz></inertia></inertial>
    <collision name="c_mu"><geometry><box><size>1 1 1</size></box></geometry>
      <surface><friction><ode><mu>0.3</mu></ode></friction></surface></collision>
    <collision name="c_both"><geometry><box><size>1 1 1</size></box></geometry>
      <surface><friction><ode><mu>0.4</mu><mu2>0.6</mu2></ode></friction></surface></collision>
    <collision name="c_ode_empty"><geometry><box><size>1 1 1</size></box></geometry>
      <surface><friction><ode/></friction></surface></collision>
    <collision name="c_none"><geometry><box><size>1 1 1</size></box></geometry></collision>
  </link>
  <link name="wheel"><pose>0 0.2 0 0 0 0</pose></link>
  <joint name="axle" type="continuous"><parent>body</parent><child>wheel</child>
    <axis><xyz>0 1 0</xyz></axis></joint>
</model></world>)";
  return {"link_properties.world", {{"link_properties.world", sdfText("1.6", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfModel& cart = need(need(doc.world, "world").models, "cart");
            const SdfLink& body = need(cart.links, "body");
            EXPECT_FALSE(body.gravity);
            EXPECT_TRUE(body.kinematic);
            EXPECT_TRUE(body.self_collide);
            EXPECT_DOUBLE_EQ(body.inertial.mass, 3.5);
            EXPECT_DOUBLE_EQ(body.inertial.ixz, 0.02);
            EXPECT_DOUBLE_EQ(body.inertial.iyy, 0.25);
            expectPose(body.inertial.T_link_inertial, sdfPose(0.1, 0, 0.05, 0, 0, 0), "inertial");
            const auto friction = [&](const std::string& c) {
              return need(body.collisions, c).ode_friction;
            };
            EXPECT_EQ(need(friction("c_mu"), "c_mu friction").mu, 0.3);
            EXPECT_FALSE(need(friction("c_mu"), "c_mu friction").mu2);
            EXPECT_EQ(need(friction("c_both"), "c_both friction").mu2, 0.6);
            EXPECT_FALSE(need(friction("c_ode_empty"), "c_ode_empty friction").mu);
            EXPECT_FALSE(friction("c_none"));
            const SdfLink& wheel = need(cart.links, "wheel");
            EXPECT_TRUE(wheel.gravity);
            EXPECT_DOUBLE_EQ(wheel.inertial.mass, 1) << "no <inertial>: the spec's mass 1";
            EXPECT_DOUBLE_EQ(wheel.inertial.ixx, 1);
            EXPECT_EQ(need(cart.joints, "axle").type, "continuous");
          }};
}

GeneratedFixture geometries() {
  const std::string world = R"(<world name="w"><model name="shapes"><static>true</static>
  <link name="link">
    <collision name="box"><geometry><box><size>1 2 3</size></box></geometry></collision>
    <collision name="cylinder"><geometry><cylinder><radius>0.5</radius><length>2</length>
      </cylinder></geometry></collision>
    <collision name="sphere"><geometry><sphere><radius>0.25</radius></sphere></geometry></collision>
    <collision name="plane"><geometry><plane><normal>0 0 1</normal><size>20 10</size></plane>
      </geometry></collision>
    <collision name="tilted"><geometry><plane><normal>0 1 1</normal><size>5 5</size></plane>
      </geometry></collision>
    <visual name="mesh"><geometry><mesh><uri>model://shapes/meshes/part.dae</uri>
      <scale>0.001 0.001 0.002</scale><submesh><name>wheel</name></submesh></mesh></geometry></visual>
    <visual name="terrain"><geometry><heightmap><uri>terrain.png</uri><size>10 10 1</size>
      </heightmap></geometry></visual>
  </link></model></world>)";
  return {"geometries.world", {{"geometries.world", sdfText("1.6", world)}},
          [](const SdfDocument& doc, const CanonicalOf&) {
            const SdfLink& link = need(need(need(doc.world, "world").models, "shapes").links,
                                       "link");
            const auto shape = [&](const std::string& c) -> const Geometry& {
              return need(need(link.collisions, c).geometry.shape, c + " shape");
            };
            expectVector(shape("box").size, {1, 2, 3}, "box");
            expectVector(shape("cylinder").size, {0.5, 0.5, 2}, "cylinder: r r length");
            expectVector(shape("sphere").size, {0.25, 0.25, 0.25}, "sphere");
            expectVector(shape("plane").size, {20, 10, 0}, "plane");
            expectVector(shape("tilted").normal.normalized(), {0, std::sqrt(0.5), std::sqrt(0.5)},
                         "tilted plane's normal direction");
            const SdfGeometry& mesh = need(link.visuals, "mesh").geometry;
            EXPECT_EQ(mesh.type, "mesh");
            EXPECT_EQ(need(mesh.shape, "mesh shape").mesh_uri, "model://shapes/meshes/part.dae");
            expectVector(mesh.shape->size, {0.001, 0.001, 0.002}, "mesh scale");
            EXPECT_EQ(mesh.submesh, "wheel");
            const SdfGeometry& terrain = need(link.visuals, "terrain").geometry;
            EXPECT_EQ(terrain.type, "heightmap");
            EXPECT_FALSE(terrain.shape) << "no simulator shape for a heightmap";
          }};
}

}  // namespace

std::vector<GeneratedFixture> appearanceFixtures() {
  return {lights(), materials(), linkProperties(), geometries()};
}

}  // namespace bullet_sim_test
