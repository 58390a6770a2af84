// The one collision shape factory: each geometry kind becomes the Bullet shape of the size
// the description gives (margins kept inside primitives), a mesh a hull on a moving body and
// its triangles on a static one, a plane only static; what cannot be built says why.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "physics/collision_shapes.h"

using namespace bullet_sim;

namespace {

/// Extents of `shape`'s bounding box at the identity pose, margin included.
btVector3 aabbMax(const btCollisionShape& shape) {
  btVector3 lo, hi;
  btTransform identity;
  identity.setIdentity();
  shape.getAabb(identity, lo, hi);
  return hi;
}

/// A cube of side 1 centred on the origin: 8 vertices, 12 triangles.
TriangleMesh unitCube() {
  MeshPart part;
  for (int i = 0; i < 8; ++i) {
    part.vertices.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  }
  part.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  TriangleMesh mesh;
  mesh.path = "cube.stl";
  mesh.parts.push_back(part);
  return mesh;
}

std::string errorOf(const Geometry& geometry, const TriangleMesh* mesh, Motion motion) {
  try {
    makeCollisionShape(geometry, mesh, motion);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(CollisionShapes, PrimitivesHaveTheDescribedSizeWithTheMarginInside) {
  const auto box = makeCollisionShape(Geometry::box(0.2, 0.4, 0.6), nullptr, Motion::Moving);
  ASSERT_EQ(box->getShapeType(), BOX_SHAPE_PROXYTYPE);
  EXPECT_NEAR(box->getMargin(), kCollisionMarginM, 1e-15);
  const btVector3 half = static_cast<const btBoxShape&>(*box).getHalfExtentsWithMargin();
  EXPECT_NEAR(half.x(), 0.1, 1e-12);
  EXPECT_NEAR(half.y(), 0.2, 1e-12);
  EXPECT_NEAR(half.z(), 0.3, 1e-12);

  // The Burger's wheel: radius 0.033, length 0.018, axis along z.
  const auto cylinder =
      makeCollisionShape(Geometry::cylinder(0.033, 0.018), nullptr, Motion::Moving);
  ASSERT_EQ(cylinder->getShapeType(), CYLINDER_SHAPE_PROXYTYPE);
  const auto& c = static_cast<const btCylinderShapeZ&>(*cylinder);
  EXPECT_EQ(c.getUpAxis(), 2);
  EXPECT_NEAR(c.getRadius(), 0.033, 1e-12);
  EXPECT_NEAR(c.getHalfExtentsWithMargin().z(), 0.009, 1e-12);

  const auto sphere = makeCollisionShape(Geometry::sphere(0.0075), nullptr, Motion::Static);
  ASSERT_EQ(sphere->getShapeType(), SPHERE_SHAPE_PROXYTYPE);
  EXPECT_NEAR(static_cast<const btSphereShape&>(*sphere).getRadius(), 0.0075, 1e-12);
}

TEST(CollisionShapes, AMeshIsAHullWhenItMovesAndItsTrianglesWhenStatic) {
  const TriangleMesh cube = unitCube();
  const Geometry stretched = Geometry::mesh("cube.stl", Eigen::Vector3d(2, 1, 0.5));
  const auto hull = makeCollisionShape(stretched, &cube, Motion::Moving);
  ASSERT_EQ(hull->getShapeType(), CONVEX_HULL_SHAPE_PROXYTYPE);
  EXPECT_EQ(static_cast<const btConvexHullShape&>(*hull).getNumPoints(), 8);
  // Scaled corners at (+-1, +-0.5, +-0.25); the hull's margin lies outside them, and its
  // bounding box adds it once more (Bullet's way with hulls): not the 4 cm default margin.
  const btVector3 hull_max = aabbMax(*hull);
  EXPECT_NEAR(hull_max.x(), 1.0 + 2 * kHullMarginM, 1e-9);
  EXPECT_NEAR(hull_max.y(), 0.5 + 2 * kHullMarginM, 1e-9);
  EXPECT_NEAR(hull_max.z(), 0.25 + 2 * kHullMarginM, 1e-9);

  const auto triangles = makeCollisionShape(stretched, &cube, Motion::Static);
  ASSERT_EQ(triangles->getShapeType(), TRIANGLE_MESH_SHAPE_PROXYTYPE);
  const btVector3 mesh_max = aabbMax(*triangles);
  EXPECT_NEAR(mesh_max.x(), 1.0 + kCollisionMarginM, 1e-9);
  EXPECT_NEAR(mesh_max.z(), 0.25 + kCollisionMarginM, 1e-9);
}

TEST(CollisionShapes, AStaticPlaneFacesItsNormalAndReachesJustAboveIt) {
  const auto plane = makeCollisionShape(Geometry::plane(0, 0), nullptr, Motion::Static);
  ASSERT_EQ(plane->getShapeType(), STATIC_PLANE_PROXYTYPE);
  const btVector3 n = static_cast<const btStaticPlaneShape&>(*plane).getPlaneNormal();
  EXPECT_NEAR(n.z(), 1.0, 1e-15);
  // Its bounding box stops kGroundSlabM above the surface, so parts higher up are not tested.
  EXPECT_NEAR(aabbMax(*plane).z(), kGroundSlabM, 1e-12);
}

TEST(CollisionShapes, WhatCannotBeBuiltSaysWhy) {
  EXPECT_EQ(errorOf(Geometry::plane(1, 1), nullptr, Motion::Moving),
            "a plane can only be static (Bullet has no moving plane)");
  EXPECT_EQ(errorOf(Geometry::mesh("package://robot/wheel.stl", Eigen::Vector3d::Ones()), nullptr,
                    Motion::Moving),
            "mesh 'package://robot/wheel.stl' has no triangles to collide");
}
