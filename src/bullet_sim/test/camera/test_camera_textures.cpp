// Textures in the Burger's camera: a world model's OGRE material script texture (found
// through model:// folder <uri>s, as TurtleBot3's autorace models give them) and a mesh
// file's own texture, each texel where Gazebo's texture coordinates put it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "../core/burger.h"
#include "../core/mesh_fixtures.h"
#include "bullet_sim/description/world_spec.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/render/world_markers.h"
#include "bullet_sim/simulation.h"
#include "burger_camera.h"

namespace {

using namespace bullet_sim;
using Eigen::Vector3d;

using bullet_sim_test::kAmbient;
using bullet_sim_test::kCamera;
using bullet_sim_test::kFocal;
using bullet_sim_test::kHeight;
using bullet_sim_test::kWidth;
using bullet_sim_test::Rgb;

/// The pixel where the world point (x, y, z) projects (the camera looks along +x).
Rgb seen(const ImageData& image, double x, double y, double z) {
  const double depth = x - kCamera.x();
  const int col = static_cast<int>(std::floor(kWidth / 2.0 - kFocal * (y - kCamera.y()) / depth));
  const int row = static_cast<int>(std::floor(kHeight / 2.0 - kFocal * (z - kCamera.z()) / depth));
  const size_t i = static_cast<size_t>(row) * image.step + 3 * static_cast<size_t>(col);
  return {image.data[i], image.data[i + 1], image.data[i + 2]};
}

/// A texel under the ambient light only, as the camera's bytes.
Rgb lit(int r, int g, int b) {
  auto byte = [](int v) { return static_cast<int>(std::min(255L, (v * std::lround(kAmbient * 256) + 128) >> 8)); };
  return {byte(r), byte(g), byte(b)};
}

/// A 2 x 2 PNG: top-left red, top-right green, bottom-left blue, bottom-right white.
void writeQuadrants(const std::string& path) {
  cv::Mat bgr(2, 2, CV_8UC3);
  bgr.at<cv::Vec3b>(0, 0) = {0, 0, 255};
  bgr.at<cv::Vec3b>(0, 1) = {0, 255, 0};
  bgr.at<cv::Vec3b>(1, 0) = {255, 0, 0};
  bgr.at<cv::Vec3b>(1, 1) = {255, 255, 255};
  ASSERT_TRUE(cv::imwrite(path, bgr));
}

void writeText(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
}

class TextureCamera : public ::testing::Test {
 protected:
  ImageData render(const WorldSpec& world, std::vector<std::string>* warnings = nullptr) {
    Simulation sim(world, SimConfig());
    sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
    CameraRenderer renderer(sim);
    ImageData image;
    renderer.render("burger", 0, &image);
    if (warnings) *warnings = renderer.warnings();
    return image;
  }

  /// A model folder `sign` whose box (0.05 deep, 0.6 wide, 0.6 high) wears material
  /// `sign_face` of its own script, as an autorace traffic sign does.
  void writeSignModel(const std::string& texture_file, bool is_static = true) {
    const std::string model = dir_ + "/sign";
    writeText(model + "/model.config",
              "<?xml version='1.0'?><model><name>sign</name><sdf version='1.6'>model.sdf</sdf>"
              "</model>");
    writeText(model + "/model.sdf",
              "<?xml version='1.0'?><sdf version='1.6'><model name='sign'><static>" +
                  std::string(is_static ? "true" : "false") +
                  "</static><link name='box'><inertial><mass>1</mass></inertial>"
                  "<collision name='c'><geometry><box><size>0.05 0.6 0.6</size></box>"
                  "</geometry></collision><visual name='visual'><geometry><box><size>0.05 0.6 0.6</size>"
              "</box></geometry><material><script>"
              "<uri>model://sign/materials/scripts</uri><uri>model://sign/materials/textures</uri>"
              "<name>sign_face</name></script></material></visual></link></model></sdf>");
    writeText(model + "/materials/scripts/sign.material",
              "material sign_face\n{\n  technique\n  {\n    pass\n    {\n      texture_unit\n"
              "      {\n        texture " + texture_file + "\n      }\n    }\n  }\n}\n");
    std::filesystem::create_directories(model + "/materials/textures");
    writeQuadrants(model + "/materials/textures/sign.png");
  }

  WorldSpec signWorld() {
    return loadWorldString(
        "<sdf version='1.6'><world name='w'><include><uri>model://sign</uri>"
        "<pose>1.5 0 0.305 0 0 0</pose></include></world></sdf>",
        "sign world", UriResolver(ResourcePaths{{dir_}, {}}));
  }

  /// A 0.6 m OBJ square facing -x at x 1.5, camera height, its material `mtl` (MTL lines),
  /// its texture coordinates u from 0 to `u_right` (v 0 at the bottom corners, 1 at the top).
  WorldSpec panelWorld(const std::string& mtl, const std::string& u_right) {
    writeText(dir_ + "/panel.mtl", "newmtl painted\n" + mtl + "\n");
    writeText(dir_ + "/panel.obj",
              "mtllib panel.mtl\nusemtl painted\n"
              "v 0 0.3 -0.3\nv 0 -0.3 -0.3\nv 0 -0.3 0.3\nv 0 0.3 0.3\n"
              "vt 0 0\nvt " + u_right + " 0\nvt " + u_right + " 1\nvt 0 1\n"
              "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    return loadWorldString(
        "<sdf version='1.6'><world name='w'><model name='panel'><static>true</static>"
        "<pose>1.5 0 0.305 0 0 0</pose><link name='l'><visual name='v'><geometry><mesh><uri>" +
            dir_ + "/panel.obj</uri></mesh></geometry></visual></link></model></world></sdf>",
        "panel world", UriResolver(ResourcePaths{}));
  }

  const std::string dir_ = bullet_sim_test::makeTempDir();
};

}  // namespace

TEST_F(TextureCamera, AScriptTextureOnABoxFaceIsUprightAndUnmirrored) {
  writeSignModel("sign.png");
  const WorldSpec world = signWorld();
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
  std::vector<std::string> warnings;
  const ImageData image = render(world, &warnings);
  EXPECT_TRUE(warnings.empty());
  // The face at x 1.475 facing the camera: Gazebo's unit_box puts the image's top-left
  // at the face's top (+z) and the camera's left (+y).
  const double x = 1.475, z = 0.305;
  EXPECT_EQ(seen(image, x, 0.15, z + 0.15), lit(255, 0, 0));
  EXPECT_EQ(seen(image, x, -0.15, z + 0.15), lit(0, 255, 0));
  EXPECT_EQ(seen(image, x, 0.15, z - 0.15), lit(0, 0, 255));
  EXPECT_EQ(seen(image, x, -0.15, z - 0.15), lit(255, 255, 255));
  // Its world marker is a mesh to be written with the texture, at the box's own pose.
  const std::vector<MarkerShape> markers = worldShapeMarkers(world);
  ASSERT_EQ(markers.size(), 1u);
  EXPECT_EQ(markers[0].type, MarkerShape::Mesh);
  ASSERT_TRUE(markers[0].textured_geometry.has_value());
  EXPECT_EQ(markers[0].textured_geometry->kind, Geometry::Box);
  EXPECT_EQ(markers[0].texture.path, world.shapes[0].texture.path);
  EXPECT_TRUE(markers[0].pose.position.isApprox(Vector3d(1.5, 0, 0.305)));
}

TEST_F(TextureCamera, AMovableModelWearsItsScriptTextureToo) {
  // The same sign, not static (as TurtleBot3's autorace tunnel and bars): a model of the
  // world simulated as a body, drawn with its texture. It stands on nothing: rendered at
  // its first pose, before any step.
  writeSignModel("sign.png", false);
  const WorldSpec world = signWorld();
  ASSERT_EQ(world.models.size(), 1u);
  const ImageData image = render(world);
  const double x = 1.475, z = 0.305;
  EXPECT_EQ(seen(image, x, 0.15, z + 0.15), lit(255, 0, 0));
  EXPECT_EQ(seen(image, x, -0.15, z - 0.15), lit(255, 255, 255));
}

TEST_F(TextureCamera, AMissingScriptTextureIsNamedAndTheBoxIsDrawnInItsColour) {
  writeSignModel("gone.png");
  const WorldSpec world = signWorld();
  ASSERT_EQ(world.warnings.size(), 1u);
  EXPECT_NE(world.warnings[0].find("gone.png"), std::string::npos) << world.warnings[0];
  EXPECT_NE(world.warnings[0].find("sign_face"), std::string::npos) << world.warnings[0];
  EXPECT_NE(world.warnings[0].find("sign.material"), std::string::npos) << world.warnings[0];
  const ImageData image = render(world);
  EXPECT_EQ(seen(image, 1.475, 0.15, 0.455), lit(255, 255, 255));  // the pass's white
}

TEST_F(TextureCamera, AnObjMeshShowsItsTextureAtItsCoordinates) {
  // A 0.6 m square facing -x at x 1.5 whose coordinates show the image's left column only
  // (u 0..0.5): red in its top half, blue in its bottom half, whatever side.
  writeQuadrants(dir_ + "/paint.png");
  const WorldSpec world = panelWorld("Kd 1 1 1\nmap_Kd paint.png", "0.5");
  std::vector<std::string> warnings;
  const ImageData image = render(world, &warnings);
  EXPECT_TRUE(warnings.empty());
  // OBJ's v runs up from the image's bottom row: v 1 (top corners) is the top row.
  EXPECT_EQ(seen(image, 1.5, 0.15, 0.305 + 0.15), lit(255, 0, 0));
  EXPECT_EQ(seen(image, 1.5, -0.15, 0.305 + 0.15), lit(255, 0, 0));
  EXPECT_EQ(seen(image, 1.5, 0.15, 0.305 - 0.15), lit(0, 0, 255));
}

TEST_F(TextureCamera, AMeshWhoseTextureIsMissingIsNamedOnce) {
  const WorldSpec world = panelWorld("Kd 0 1 0\nmap_Kd nowhere.png", "1");
  std::vector<std::string> warnings;
  const ImageData image = render(world, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], dir_ + "/panel.obj: texture 'nowhere.png' not found beside the mesh "
                                "or in ../materials/textures: drawn in its colour");
  EXPECT_EQ(seen(image, 1.5, 0, 0.305), lit(0, 255, 0));  // the material's own green
}
