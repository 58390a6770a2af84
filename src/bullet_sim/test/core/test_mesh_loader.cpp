// Mesh files through assimp: STL (binary, ASCII), COLLADA with <unit> (and <up_axis> ignored), OBJ
// with MTL colours; the cache; unreadable files. Every file is written by the test.
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include <assimp/version.h>
#include <gtest/gtest.h>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/errors.h"
#include "mesh_fixtures.h"

using namespace bullet_sim;
using bullet_sim_test::boxTriangles;
using Eigen::Vector3d;

namespace {

Eigen::AlignedBox3d boundsOf(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const MeshPart& part : mesh.parts)
    for (const Vector3d& v : part.vertices) box.extend(v);
  return box;
}

/// Every triangle's normal points away from the mesh's centre (a closed convex mesh).
void expectOutwardWinding(const TriangleMesh& mesh) {
  const Vector3d centre = boundsOf(mesh).center();
  for (const MeshPart& part : mesh.parts) {
    for (const auto& t : part.triangles) {
      const Vector3d& a = part.vertices[t[0]];
      const Vector3d n = (part.vertices[t[1]] - a).cross(part.vertices[t[2]] - a);
      EXPECT_GT(n.dot(a - centre), 0);
    }
  }
}

::testing::AssertionResult near(const Vector3d& actual, const Vector3d& expected) {
  if ((actual - expected).norm() < 1e-6) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual.transpose() << " is not " << expected.transpose();
}

std::string loadErrorOf(const std::string& path) {
  try {
    readMeshFile(path);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

class MeshFiles : public ::testing::Test {
 protected:
  std::string file(const std::string& name) const { return dir_ + "/" + name; }
  const std::string dir_ = bullet_sim_test::makeTempDir();
};

}  // namespace

TEST_F(MeshFiles, BinaryAndAsciiStlCubeComeOutAsWritten) {
  const auto cube = boxTriangles(Vector3d(0.2, 0.4, 0.6), Vector3d(1, 2, 3));
  bullet_sim_test::writeBinaryStl(file("cube_binary.stl"), cube);
  bullet_sim_test::writeAsciiStl(file("cube_ascii.stl"), cube);
  for (const std::string name : {"cube_binary.stl", "cube_ascii.stl"}) {
    SCOPED_TRACE(name);
    const TriangleMesh mesh = readMeshFile(file(name));
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.triangleCount(), 12u);
    EXPECT_EQ(mesh.vertexCount(), 8u);  // corners shared between faces
    EXPECT_FALSE(mesh.parts[0].rgba.has_value());  // STL has no colour: the visual's is used
    const Eigen::AlignedBox3d box = boundsOf(mesh);
    EXPECT_TRUE(near(box.min(), Vector3d(0.9, 1.8, 2.7)));
    EXPECT_TRUE(near(box.max(), Vector3d(1.1, 2.2, 3.3)));
    expectOutwardWinding(mesh);
  }
}

TEST_F(MeshFiles, ColladaTaggedYUpWithZUpDataStandsAsWrittenInMetres) {
  // As TurtleBot3's wall.dae: tagged Y_UP, in inches, its data z up. In the file: 100 in
  // along x, 50 in along y, 200 in high along z, standing on z = 0. Gazebo Classic applies
  // <unit> and ignores <up_axis> (gazebo-classic issue 1305): 2.54 m x 1.27 m, 5.08 m high.
  const auto box = boxTriangles(Vector3d(100, 50, 200), Vector3d(50, 25, 100));
  bullet_sim_test::writeCollada(file("y_up_inch.dae"), box, 0.0254, "Y_UP",
                                Eigen::Vector4f(0.8f, 0.1f, 0.2f, 1.0f));
  const TriangleMesh mesh = readMeshFile(file("y_up_inch.dae"));
  ASSERT_EQ(mesh.parts.size(), 1u);
  EXPECT_EQ(mesh.triangleCount(), 12u);
  const Eigen::AlignedBox3d bounds = boundsOf(mesh);
  EXPECT_TRUE(near(bounds.min(), Vector3d(0, 0, 0))) << bounds.min().transpose();
  EXPECT_TRUE(near(bounds.max(), Vector3d(2.54, 1.27, 5.08))) << bounds.max().transpose();
  ASSERT_TRUE(mesh.parts[0].rgba.has_value());
  EXPECT_TRUE(mesh.parts[0].rgba->isApprox(Eigen::Vector4f(0.8f, 0.1f, 0.2f, 1.0f)));
  expectOutwardWinding(mesh);
}

TEST_F(MeshFiles, ColladaUpAxisNeverTurnsTheData) {
  // The same box in centimetres under each tag: the same metres every time.
  const auto box = boxTriangles(Vector3d(100, 50, 20), Vector3d(50, 25, 10));
  for (const std::string up : {"X_UP", "Y_UP", "Z_UP"}) {
    SCOPED_TRACE(up);
    const std::string name = "box_" + up + ".dae";
    bullet_sim_test::writeCollada(file(name), box, 0.01, up,
                                  Eigen::Vector4f(0.1f, 0.9f, 0.1f, 1.0f));
    const Eigen::AlignedBox3d bounds = boundsOf(readMeshFile(file(name)));
    EXPECT_TRUE(near(bounds.min(), Vector3d(0, 0, 0))) << bounds.min().transpose();
    EXPECT_TRUE(near(bounds.max(), Vector3d(1.0, 0.5, 0.2))) << bounds.max().transpose();
  }
}

TEST_F(MeshFiles, ObjGivesOnePartPerMaterialWithItsDiffuseColour) {
  const auto left = boxTriangles(Vector3d(0.1, 0.1, 0.1), Vector3d(0, 1, 0));
  const auto right = boxTriangles(Vector3d(0.2, 0.2, 0.2), Vector3d(0, -1, 0));
  bullet_sim_test::writeObj(file("two.obj"), {left, right},
                            {Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(0, 0, 1)});
  const TriangleMesh mesh = readMeshFile(file("two.obj"));
  ASSERT_EQ(mesh.parts.size(), 2u);
  int red = 0, blue = 0;
  for (const MeshPart& part : mesh.parts) {
    ASSERT_TRUE(part.rgba.has_value());
    EXPECT_EQ(part.triangles.size(), 12u);
    Eigen::AlignedBox3d box;
    for (const Vector3d& v : part.vertices) box.extend(v);
    if (part.rgba->isApprox(Eigen::Vector4f(1, 0, 0, 1))) {
      ++red;
      EXPECT_NEAR(box.center().y(), 1.0, 1e-6);
      EXPECT_NEAR(box.sizes().x(), 0.1, 1e-6);
    } else if (part.rgba->isApprox(Eigen::Vector4f(0, 0, 1, 1))) {
      ++blue;
      EXPECT_NEAR(box.center().y(), -1.0, 1e-6);
      EXPECT_NEAR(box.sizes().x(), 0.2, 1e-6);
    }
  }
  EXPECT_EQ(red, 1);
  EXPECT_EQ(blue, 1);
}

/// A unit cube in OBJ: 8 corners, each face with its own 4 texture coordinates, so a
/// corner has 3 different ones.
/// The unit cube's faces by corner (1-based, corner i at (i-1 & 1, i-1 >> 1 & 1, i-1 >> 2 & 1)).
constexpr int kCubeFaces[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                                  {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};

std::string cubeWithFaceCoordinates() {
  std::string obj = "mtllib cube.mtl\nusemtl paint\n";
  for (int i = 0; i < 8; ++i) {
    obj += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " +
           std::to_string((i >> 2) & 1) + "\n";
  }
  for (int f = 0; f < 6; ++f) {
    obj += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf";
    for (int c = 0; c < 4; ++c) {
      obj += " " + std::to_string(kCubeFaces[f][c]) + "/" + std::to_string(4 * f + c + 1);
    }
    obj += "\n";
  }
  return obj;
}

TEST_F(MeshFiles, CornersJoinUnlessATextureNeedsTheirCoordinates) {
  bullet_sim_test::writeText(file("paint.png"), "an image's bytes");
  for (const std::string texture : {"", "paint.png"}) {
    SCOPED_TRACE("map_Kd '" + texture + "'");
    bullet_sim_test::writeText(file("cube.obj"), cubeWithFaceCoordinates());
    bullet_sim_test::writeText(file("cube.mtl"),
              "newmtl paint\nKd 0.5 0.5 0.5\n" + (texture.empty() ? "" : "map_Kd " + texture + "\n"));
    const TriangleMesh mesh = readMeshFile(file("cube.obj"));
    EXPECT_EQ(mesh.triangleCount(), 12u);
    // Untextured, the 24 face corners are the cube's 8 corners; textured, a corner stays
    // apart for each different coordinate it has (the c-th corner of a face has the c-th).
    std::set<std::pair<int, int>> corner_coordinates;
    for (const auto& face : kCubeFaces) {
      for (int c = 0; c < 4; ++c) corner_coordinates.insert({face[c], c});
    }
    EXPECT_EQ(mesh.vertexCount(), texture.empty() ? 8u : corner_coordinates.size());
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].uvs.size(), texture.empty() ? 0u : corner_coordinates.size());
  }
}

TEST_F(MeshFiles, CacheReadsAFileOnceWhileItIsUsedAndAgainWhenItChanges) {
  bullet_sim_test::writeBinaryStl(file("shared.stl"), boxTriangles(Vector3d(1, 1, 1)));
  MeshCache cache;
  const auto first = cache.load(file("shared.stl"));
  const auto second = cache.load(file("shared.stl"));
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(cache.fileReads(), 1u);
  // Rewritten with two boxes: a different file now.
  auto two = boxTriangles(Vector3d(1, 1, 1));
  const auto more = boxTriangles(Vector3d(1, 1, 1), Vector3d(3, 0, 0));
  two.insert(two.end(), more.begin(), more.end());
  bullet_sim_test::writeBinaryStl(file("shared.stl"), two);
  const auto third = cache.load(file("shared.stl"));
  EXPECT_EQ(cache.fileReads(), 2u);
  EXPECT_EQ(third->triangleCount(), 24u);
  EXPECT_EQ(first->triangleCount(), 12u);  // its users keep the old one
}

TEST_F(MeshFiles, CorruptStlNamesTheFileAndAssimpsReason) {
  bullet_sim_test::writeText(file("corrupt.stl"), "this is not a mesh\n");
  const std::string error = loadErrorOf(file("corrupt.stl"));
  EXPECT_EQ(error.rfind(file("corrupt.stl") + ": cannot read mesh: ", 0), 0u) << error;
  EXPECT_NE(error.find("STL"), std::string::npos) << error;  // assimp's own words
}

TEST_F(MeshFiles, EmptyAndMissingFilesAreNamed) {
  bullet_sim_test::writeText(file("empty.stl"), "");
  EXPECT_EQ(loadErrorOf(file("empty.stl")),
            file("empty.stl") + ": cannot read mesh: File is empty");
  const std::string missing = loadErrorOf(file("missing.dae"));
  EXPECT_EQ(missing.rfind(file("missing.dae") + ": cannot read mesh: ", 0), 0u) << missing;
}

// Found by fuzz_mesh: assimp 5.2 crashes on these files (a failed assertion, a null
// pointer); readMeshFile reads in a child process, so they are load errors naming the file.
TEST(MeshCrashes, ColladaTrianglesWithoutIndicesCrashAssimpNotTheLoader) {
  const std::string path =
      std::string(BULLET_SIM_FIXTURES) + "/mesh_collada_triangles_without_p.dae";
  EXPECT_EQ(loadErrorOf(path), path + ": cannot read mesh: assimp crashed reading it (Aborted)");
}

TEST(MeshCrashes, ColladaEmptyFloatArrayCrashesAssimpNotTheLoader) {
  const std::string path =
      std::string(BULLET_SIM_FIXTURES) + "/mesh_collada_empty_float_array.dae";
  // assimp 5.2 (Debian 12) dies on it; 5.4 (Debian 13) checks the accessor and says so.
  const bool checks_accessors = aiGetVersionMajor() > 5 ||
                                (aiGetVersionMajor() == 5 && aiGetVersionMinor() >= 4);
  EXPECT_EQ(loadErrorOf(path),
            path + ": cannot read mesh: " +
                (checks_accessors ? "Not enough data for accessor"
                                  : "assimp crashed reading it (Segmentation fault)"));
}

TEST(MeshCrashes, ATriangleReadInTheChildProcessArrivesWhole) {
  // The wire format carries vertices, triangles and the file's colour (a red lambert,
  // millimetres, tagged Y up and read as written: the corner (1000, 0, 0) mm is (1, 0, 0) m,
  // (0, 1000, 0) is (0, 1, 0)).
  const TriangleMesh mesh =
      readMeshFile(std::string(BULLET_SIM_FIXTURES) + "/mesh_red_triangle.dae");
  ASSERT_EQ(mesh.parts.size(), 1u);
  const MeshPart& part = mesh.parts[0];
  ASSERT_EQ(part.triangles.size(), 1u);
  ASSERT_TRUE(part.rgba.has_value());
  EXPECT_TRUE(part.rgba->isApprox(Eigen::Vector4f(1, 0, 0, 1)));
  EXPECT_TRUE(near(part.vertices[part.triangles[0][0]], Vector3d(0, 0, 0)));
  EXPECT_TRUE(near(part.vertices[part.triangles[0][1]], Vector3d(1, 0, 0)));
  EXPECT_TRUE(near(part.vertices[part.triangles[0][2]], Vector3d(0, 1, 0)));
}

TEST_F(MeshFiles, ColladaWithoutTrianglesIsAnError) {
  bullet_sim_test::writeCollada(file("nothing.dae"), {}, 1.0, "Z_UP",
                                Eigen::Vector4f(1, 1, 1, 1));
  EXPECT_EQ(loadErrorOf(file("nothing.dae")), file("nothing.dae") + ": mesh has no triangles");
}
