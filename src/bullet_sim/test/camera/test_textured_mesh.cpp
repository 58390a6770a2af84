// The textured meshes written for RViz: Gazebo's box coordinates in an OBJ, its MTL naming
// the image beside it, written once.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../core/mesh_fixtures.h"
#include "bullet_sim/render/textured_mesh.h"

namespace {

using namespace bullet_sim;
namespace fs = std::filesystem;

struct Obj {
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector2d> vt;
  std::vector<std::array<std::pair<int, int>, 3>> faces;  ///< (v, vt), 0-based
  std::string mtllib;
};

Obj readObj(const std::string& path) {
  Obj obj;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      Eigen::Vector3d p;
      words >> p.x() >> p.y() >> p.z();
      obj.v.push_back(p);
    } else if (tag == "vt") {
      Eigen::Vector2d t;
      words >> t.x() >> t.y();
      obj.vt.push_back(t);
    } else if (tag == "f") {
      std::array<std::pair<int, int>, 3> face;
      for (auto& corner : face) {
        std::string item;
        words >> item;
        const size_t slash = item.find('/');
        corner = {std::stoi(item.substr(0, slash)) - 1, std::stoi(item.substr(slash + 1)) - 1};
      }
      obj.faces.push_back(face);
    } else if (tag == "mtllib") {
      words >> obj.mtllib;
    }
  }
  return obj;
}

/// The OBJ coordinates (v up from the image's bottom) at a corner of the face with outward
/// normal `n`, found among the faces whose corners all lie on that side.
Eigen::Vector2d coordinatesAt(const Obj& obj, const Eigen::Vector3d& corner, const Eigen::Vector3d& n) {
  for (const auto& face : obj.faces) {
    bool on_side = true;
    for (const auto& c : face) on_side &= std::abs(obj.v[c.first].dot(n) - 0.5) < 1e-9;
    if (!on_side) continue;
    for (const auto& c : face) {
      if ((obj.v[c.first] - corner).norm() < 1e-9) return obj.vt[c.second];
    }
  }
  ADD_FAILURE() << "no corner " << corner.transpose() << " on the side " << n.transpose();
  return Eigen::Vector2d::Constant(-1);
}

}  // namespace

TEST(TexturedMesh, ABoxGetsGazebosCoordinatesAndItsImageBesideIt) {
  const std::string dir = bullet_sim_test::makeTempDir();
  bullet_sim_test::writeText(dir + "/sign.png", "image bytes");
  TextureRef texture;
  texture.path = dir + "/sign.png";
  std::string reason;
  const std::string path =
      writeTexturedMesh(Geometry::box(1, 1, 1), texture, dir + "/cache", &reason);
  ASSERT_FALSE(path.empty()) << reason;
  const Obj obj = readObj(path);
  EXPECT_EQ(obj.faces.size(), 12u);
  ASSERT_EQ(obj.vt.size(), obj.v.size());
  // The face towards -x, seen from outside: image top-left at (+y, +z), bottom-right at
  // (-y, -z); OBJ counts v up from the bottom row.
  const Eigen::Vector3d minus_x(-1, 0, 0);
  EXPECT_TRUE(coordinatesAt(obj, {-0.5, 0.5, 0.5}, minus_x).isApprox(Eigen::Vector2d(0, 1)));
  EXPECT_TRUE(coordinatesAt(obj, {-0.5, -0.5, -0.5}, minus_x).isApprox(Eigen::Vector2d(1, 0)));
  // The top face: u from +y to -y, image top at +x.
  const Eigen::Vector3d plus_z(0, 0, 1);
  EXPECT_TRUE(coordinatesAt(obj, {0.5, 0.5, 0.5}, plus_z).isApprox(Eigen::Vector2d(0, 1)));
  // The MTL names the image by a name beside it, which leads to the texture.
  const fs::path folder = fs::path(path).parent_path();
  std::ifstream mtl(folder / obj.mtllib);
  std::stringstream text;
  text << mtl.rdbuf();
  const std::string mtl_text = text.str();
  const size_t at = mtl_text.find("map_Kd ");
  ASSERT_NE(at, std::string::npos) << mtl_text;
  const std::string image = mtl_text.substr(at + 7, mtl_text.find('\n', at) - at - 7);
  EXPECT_EQ(fs::canonical(folder / image), fs::canonical(texture.path));
  // Written once: a second call names the same file and leaves it as it was.
  const auto written = fs::last_write_time(path);
  EXPECT_EQ(writeTexturedMesh(Geometry::box(1, 1, 1), texture, dir + "/cache", &reason), path);
  EXPECT_EQ(fs::last_write_time(path), written);
  EXPECT_NE(writeTexturedMesh(Geometry::box(1, 2, 1), texture, dir + "/cache", &reason), path);
}

TEST(TexturedMesh, AnInfinitePlaneHasNoCoordinatesAndSaysSo) {
  TextureRef texture;
  texture.path = "/nowhere/course.png";
  std::string reason;
  EXPECT_EQ(writeTexturedMesh(Geometry::plane(0, 0), texture,
                              bullet_sim_test::makeTempDir(), &reason), "");
  EXPECT_EQ(reason, "a plane has no texture coordinates");
}
