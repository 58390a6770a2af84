#include "sim_render/scene.h"
#include "sim_render/tessellation.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace sim_render;

namespace {

const Eigen::Vector4f kGrey(0.5f, 0.5f, 0.5f, 1.0f);

std::string tessellationError(const ShapeSpec& spec) {
  try {
    tessellate(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Every face of a convex shape centred on its origin points away from the origin, and the
// stored normal agrees with the triangle's winding.
void expectOutwardUnitNormals(const Mesh& mesh) {
  ASSERT_EQ(mesh.triangles.size(), mesh.face_normals.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    const Eigen::Vector3d& n = mesh.face_normals[t];
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT(((a + b + c) / 3.0).dot(n), 0.0) << "triangle " << t;
    EXPECT_GT((b - a).cross(c - a).dot(n), 0.0) << "triangle " << t;
  }
}

}  // namespace

TEST(Tessellation, BoxHasTwelveOutwardTriangles) {
  const Mesh mesh = tessellate(ShapeSpec::box(0.2, 0.4, 0.6, kGrey));
  EXPECT_EQ(mesh.triangles.size(), 12u);
  expectOutwardUnitNormals(mesh);
  EXPECT_NEAR(mesh.bounding_radius_m, std::sqrt(0.01 + 0.04 + 0.09), 1e-12);
}

TEST(Tessellation, CylinderAndSphereAreClosedAndOutward) {
  TessellationOptions options;
  options.cylinder_segments = 16;
  const Mesh cylinder = tessellate(ShapeSpec::cylinder(0.1, 0.5, kGrey), options);
  EXPECT_EQ(cylinder.triangles.size(), 16u * 4u);  // two per side facet, one per cap
  expectOutwardUnitNormals(cylinder);
  for (const Eigen::Vector3d& v : cylinder.vertices) {
    EXPECT_LE(std::hypot(v.x(), v.y()), 0.1 + 1e-12);
    EXPECT_LE(std::abs(v.z()), 0.25 + 1e-12);
  }
  const Mesh sphere = tessellate(ShapeSpec::sphere(0.3, kGrey));
  expectOutwardUnitNormals(sphere);
  for (const Eigen::Vector3d& v : sphere.vertices) EXPECT_NEAR(v.norm(), 0.3, 1e-12);
}

TEST(Tessellation, PlaneFacesItsNormal) {
  ShapeSpec plane = ShapeSpec::plane(4, 2, kGrey);
  plane.normal = Eigen::Vector3d(1, 0, 0);
  const Mesh mesh = tessellate(plane);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  for (const Eigen::Vector3d& n : mesh.face_normals) EXPECT_NEAR(n.x(), 1.0, 1e-12);
  for (const Eigen::Vector3d& v : mesh.vertices) EXPECT_NEAR(v.x(), 0.0, 1e-12);

  TessellationOptions options;
  options.infinite_plane_half_extent_m = 500;
  const Mesh infinite = tessellate(ShapeSpec::plane(0, 0, kGrey), options);
  EXPECT_NEAR(infinite.bounding_radius_m, 500 * std::sqrt(2.0), 1e-9);
}

TEST(Tessellation, BadSizesAreNamed) {
  EXPECT_EQ(tessellationError(ShapeSpec::box(1, -1, 1, kGrey)), "box size y must be finite and > 0, got -1");
  EXPECT_EQ(tessellationError(ShapeSpec::cylinder(0, 1, kGrey)), "cylinder radius must be finite and > 0, got 0");
  EXPECT_EQ(tessellationError(ShapeSpec::sphere(NAN, kGrey)), "sphere radius must be finite and > 0, got nan");
  EXPECT_EQ(tessellationError(ShapeSpec::plane(3, 0, kGrey)), "plane size y must be finite and > 0, got 0");
  ShapeSpec no_normal = ShapeSpec::plane(1, 1, kGrey);
  no_normal.normal = Eigen::Vector3d::Zero();
  EXPECT_NE(tessellationError(no_normal).find("plane normal"), std::string::npos);
}

namespace {

/// A unit tetrahedron with counter-clockwise faces seen from outside, corner at the origin.
std::shared_ptr<const Mesh> tetrahedron() {
  auto mesh = std::make_shared<Mesh>();
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

// Every face points away from the tetrahedron's centroid, normal agreeing with the winding.
void expectOutwardFrom(const Mesh& mesh, const Eigen::Vector3d& centre) {
  ASSERT_EQ(mesh.triangles.size(), mesh.face_normals.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& n = mesh.face_normals[t];
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT((a - centre).dot(n), 0.0) << "triangle " << t;
    EXPECT_GT((mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).dot(n), 0.0);
  }
}

}  // namespace

TEST(Tessellation, MeshIsScaledWithOutwardNormalsEvenWhenMirrored) {
  const Mesh scaled = tessellate(ShapeSpec::mesh(tetrahedron(), Eigen::Vector3d(2, 3, 4), kGrey));
  ASSERT_EQ(scaled.vertices.size(), 4u);
  EXPECT_TRUE(scaled.vertices[3].isApprox(Eigen::Vector3d(0, 0, 4)));
  EXPECT_NEAR(scaled.bounding_radius_m, 4.0, 1e-12);
  expectOutwardFrom(scaled, Eigen::Vector3d(2, 3, 4) / 4);
  // A negative scale mirrors the mesh; its faces must still point outwards.
  const Mesh mirrored = tessellate(ShapeSpec::mesh(tetrahedron(), Eigen::Vector3d(-1, 1, 1), kGrey));
  expectOutwardFrom(mirrored, Eigen::Vector3d(-1, 1, 1) / 4);
}

TEST(Tessellation, BadMeshesAreNamed) {
  EXPECT_EQ(tessellationError(ShapeSpec::mesh(nullptr, Eigen::Vector3d::Ones(), kGrey)),
            "mesh has no triangles");
  EXPECT_EQ(tessellationError(ShapeSpec::mesh(tetrahedron(), Eigen::Vector3d(1, 0, 1), kGrey)),
            "mesh scale must be finite and non-zero, got 1 0 1");
  auto broken = std::make_shared<Mesh>(*tetrahedron());
  broken->triangles.push_back({0, 1, 9});
  EXPECT_EQ(tessellationError(ShapeSpec::mesh(broken, Eigen::Vector3d::Ones(), kGrey)),
            "mesh triangle index 9 is beyond its 4 vertices");
}

TEST(Scene, AddMoveRecolourRemove) {
  Scene scene;
  const ShapeId a = scene.add(ShapeSpec::box(1, 1, 1, kGrey), Eigen::Isometry3d::Identity());
  const ShapeId b = scene.add(ShapeSpec::sphere(1, kGrey), Eigen::Isometry3d::Identity());
  EXPECT_NE(a, b);
  EXPECT_EQ(scene.size(), 2u);

  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  moved.translation() = Eigen::Vector3d(1, 2, 3);
  scene.setPose(a, moved);
  scene.setColor(b, Eigen::Vector4f(1, 0, 0, 1));
  EXPECT_TRUE(scene.shape(a).T_world_shape.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_EQ(scene.shape(b).spec.rgba.x(), 1.0f);

  EXPECT_TRUE(scene.remove(a));
  EXPECT_FALSE(scene.remove(a));
  EXPECT_FALSE(scene.contains(a));
  EXPECT_TRUE(scene.contains(b));
  EXPECT_EQ(scene.shape(b).spec.kind, Geometry::Sphere);
  const ShapeId c = scene.add(ShapeSpec::box(1, 1, 1, kGrey), Eigen::Isometry3d::Identity());
  EXPECT_NE(c, a);  // ids are never reused
  scene.clear();
  EXPECT_EQ(scene.size(), 0u);
}

TEST(Scene, UnknownIdAndBadShapeThrow) {
  Scene scene;
  try {
    scene.setPose(42, Eigen::Isometry3d::Identity());
    FAIL() << "setPose accepted an unknown id";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("42"), std::string::npos) << e.what();
  }
  EXPECT_THROW(scene.setColor(7, kGrey), std::out_of_range);
  EXPECT_THROW(scene.add(ShapeSpec::box(0, 1, 1, kGrey), Eigen::Isometry3d::Identity()), std::invalid_argument);
  EXPECT_EQ(scene.size(), 0u);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
