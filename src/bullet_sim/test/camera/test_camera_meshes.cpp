// The Burger's camera sees mesh visuals of the world and of robots where their geometry
// projects through K, in their file's colours (or the visual's, for parts without one).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../core/burger.h"
#include "../core/mesh_fixtures.h"
#include "bullet_sim/render/camera_renderer.h"
#include "bullet_sim/simulation.h"
#include "burger_camera.h"

namespace {

using namespace bullet_sim;
using bullet_sim_test::boxTriangles;
using Eigen::Vector3d;

using bullet_sim_test::kAmbient;
using bullet_sim_test::kCamera;
using bullet_sim_test::kFocal;
using bullet_sim_test::kHeight;
using bullet_sim_test::kWidth;
using bullet_sim_test::pixel;
using bullet_sim_test::Rgb;

/// A colour under the ambient light only, as bytes.
Rgb ambientOnly(double r, double g, double b) {
  auto byte = [](double v) { return static_cast<int>(std::lround(v * kAmbient * 255.0)); };
  return {byte(r), byte(g), byte(b)};
}

/// First and last column of `row` whose pixel is `colour`; -1 when none.
std::pair<int, int> columnSpan(const ImageData& image, int row, const Rgb& colour) {
  int first = -1, last = -1;
  for (int col = 0; col < kWidth; ++col) {
    if (!(pixel(image, col, row) == colour)) continue;
    if (first < 0) first = col;
    last = col;
  }
  return {first, last};
}

/// Column where a point at lateral offset y and depth x (camera frame) projects.
double column(double x, double y) { return kWidth / 2.0 - kFocal * y / x; }

class MeshCamera : public ::testing::Test {
 protected:
  ImageData renderWith(const WorldSpec& world, const RobotSpec* other, const Pose3& other_pose) {
    Simulation sim(world, SimConfig());
    sim.spawnRobot("burger", bullet_sim_test::burgerSpec(), Pose3());
    if (other) sim.spawnRobot("other", *other, other_pose);
    CameraRenderer renderer(sim);
    ImageData image;
    renderer.render("burger", 0, &image);
    EXPECT_TRUE(renderer.warnings().empty());
    return image;
  }
  const std::string dir_ = bullet_sim_test::makeTempDir();
};

}  // namespace

TEST_F(MeshCamera, WorldMeshesWhereTheyProjectInTheirOwnOrTheirVisualsColour) {
  // A red COLLADA box 0.4 deep, 0.6 wide, 0.3 high at camera height, 1.5 m ahead; a blue
  // STL box (STL has no colour: the SDF material's) 0.4 m to its left... both facing -x.
  bullet_sim_test::writeCollada(dir_ + "/red.dae", boxTriangles(Vector3d(0.4, 0.6, 0.3)), 1.0,
                                "Z_UP", Eigen::Vector4f(0.9f, 0.1f, 0.1f, 1));
  bullet_sim_test::writeBinaryStl(dir_ + "/plain.stl", boxTriangles(Vector3d(0.4, 0.2, 0.3)));
  auto model = [&](const std::string& name, const std::string& pose, const std::string& file,
                   const std::string& material) {
    return "<model name='" + name + "'><static>true</static><pose>" + pose +
           "</pose><link name='l'><visual name='v'><geometry><mesh><uri>" + dir_ + "/" + file +
           "</uri></mesh></geometry>" + material + "</visual></link></model>";
  };
  const WorldSpec world = loadWorldString(
      "<sdf version='1.6'><world name='w'>" +
          model("red", "1.5 0 0.305 0 0 0", "red.dae", "") +
          model("blue", "1.5 0.6 0.305 0 0 0", "plain.stl",
                "<material><diffuse>0 0 1 1</diffuse></material>") +
          "</world></sdf>",
      "mesh world", UriResolver(ResourcePaths{}));
  const ImageData image = renderWith(world, nullptr, Pose3());

  const double depth = 1.5 - 0.2 - kCamera.x();  // near faces at x 1.3
  const Rgb red = ambientOnly(0.9, 0.1, 0.1), blue = ambientOnly(0, 0, 1);
  EXPECT_EQ(pixel(image, kWidth / 2, kHeight / 2), red);
  const auto red_span = columnSpan(image, kHeight / 2, red);
  EXPECT_NEAR(red_span.first, column(depth, 0.3), 1.0);
  EXPECT_NEAR(red_span.second, column(depth, -0.3), 1.0);
  const auto blue_span = columnSpan(image, kHeight / 2, blue);
  EXPECT_NEAR(blue_span.first, column(depth, 0.7), 1.0);
  EXPECT_NEAR(blue_span.second, column(depth, 0.5), 1.0);
  // Top and bottom edges of the red box: z +-0.15 about the camera's height.
  int top = -1, bottom = -1;
  for (int row = 0; row < kHeight; ++row) {
    if (!(pixel(image, kWidth / 2, row) == red)) continue;
    if (top < 0) top = row;
    bottom = row;
  }
  EXPECT_NEAR(top, kHeight / 2.0 - kFocal * 0.15 / depth, 1.0);
  EXPECT_NEAR(bottom, kHeight / 2.0 + kFocal * 0.15 / depth, 1.0);
}

TEST_F(MeshCamera, RobotMeshVisualsAreDrawnAtTheirLinkInTheirColours) {
  // A robot whose link carries a green COLLADA box (its own colour wins over the URDF's
  // white, as in RViz) and a plain STL box in the URDF's yellow beside it.
  bullet_sim_test::writeCollada(dir_ + "/green.dae", boxTriangles(Vector3d(0.2, 0.2, 0.2)), 1.0,
                                "Z_UP", Eigen::Vector4f(0.1f, 0.8f, 0.1f, 1));
  bullet_sim_test::writeAsciiStl(dir_ + "/plain.stl", boxTriangles(Vector3d(0.2, 0.2, 0.2)));
  const std::string urdf =
      "<robot name='blocks'><link name='base_link'>"
      "<visual><geometry><mesh filename='" + dir_ + "/green.dae'/></geometry>"
      "<material name='white'><color rgba='1 1 1 1'/></material></visual>"
      "<visual><origin xyz='0 0.4 0'/><geometry><mesh filename='" + dir_ + "/plain.stl'/>"
      "</geometry><material name='yellow'><color rgba='1 1 0 1'/></material></visual>"
      "<inertial><mass value='1'/><inertia ixx='0.01' ixy='0' ixz='0' iyy='0.01' iyz='0' "
      "izz='0.01'/></inertial></link></robot>";
  const RobotSpec blocks = parseRobot(urdf, "blocks", UriResolver(ResourcePaths{}));
  EXPECT_TRUE(blocks.warnings.empty());
  Pose3 pose;
  pose.position = Vector3d(1.2, 0, kCamera.z());
  const ImageData image = renderWith(bullet_sim_test::flatWorld(), &blocks, pose);

  const double depth = 1.2 - 0.1 - kCamera.x();
  const Rgb green = ambientOnly(0.1, 0.8, 0.1), yellow = ambientOnly(1, 1, 0);
  const auto green_span = columnSpan(image, kHeight / 2, green);
  EXPECT_NEAR(green_span.first, column(depth, 0.1), 1.0);
  EXPECT_NEAR(green_span.second, column(depth, -0.1), 1.0);
  const auto yellow_span = columnSpan(image, kHeight / 2, yellow);
  EXPECT_NEAR(yellow_span.first, column(depth, 0.5), 1.0);
  EXPECT_NEAR(yellow_span.second, column(depth, 0.3), 1.0);
}
