#include "physics/collision_shapes.h"

#include <cmath>
#include <stdexcept>

#include <BulletCollision/CollisionShapes/btShapeHull.h>

#include "physics/bullet_convert.h"

namespace bullet_sim {
namespace {

/// A BVH triangle-mesh shape that keeps the triangles it points to alive.
class OwningTriangleMeshShape : public btBvhTriangleMeshShape {
 public:
  explicit OwningTriangleMeshShape(std::unique_ptr<btTriangleMesh> triangles)
      : btBvhTriangleMeshShape(triangles.get(), true), triangles_(std::move(triangles)) {}

 private:
  std::unique_ptr<btTriangleMesh> triangles_;
};

/// A ground plane whose bounding box stops just above the plane when its normal is a world
/// axis: Bullet then skips the parts of a robot (lidar, poles, plate) that cannot touch the
/// ground instead of testing all of them every step, and horizontal lidar rays no longer
/// test the ground at all.
class GroundPlaneShape : public btStaticPlaneShape {
 public:
  using btStaticPlaneShape::btStaticPlaneShape;
  void getAabb(const btTransform& t, btVector3& aabb_min, btVector3& aabb_max) const override {
    btStaticPlaneShape::getAabb(t, aabb_min, aabb_max);
    const btVector3 n = t.getBasis() * getPlaneNormal();
    for (int axis = 0; axis < 3; ++axis) {
      if (std::fabs(std::fabs(n[axis]) - 1.0) > 1e-12) continue;
      const double surface = t.getOrigin()[axis] + n[axis] * getPlaneConstant();
      if (n[axis] > 0) aabb_max[axis] = surface + kGroundSlabM;
      else aabb_min[axis] = surface - kGroundSlabM;
    }
  }
};

template <typename Shape>
std::unique_ptr<btConvexShape> withMargin(std::unique_ptr<Shape> shape) {
  shape->setMargin(kCollisionMarginM);
  return shape;
}

std::unique_ptr<btConvexShape> makeBox(const Eigen::Vector3d& size) {
  return withMargin(std::make_unique<btBoxShape>(toBt(size * 0.5)));
}

std::unique_ptr<btConvexShape> makeCylinder(const Eigen::Vector3d& size) {
  return withMargin(
      std::make_unique<btCylinderShapeZ>(btVector3(size.x(), size.y(), size.z() * 0.5)));
}

std::unique_ptr<btConvexShape> makeSphere(double radius_m) {
  return withMargin(std::make_unique<btSphereShape>(radius_m));
}

/// The convex hull of every vertex of `mesh` scaled by `scale`.
std::unique_ptr<btConvexHullShape> makeConvexHull(const TriangleMesh& mesh,
                                                  const Eigen::Vector3d& scale) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const MeshPart& part : mesh.parts) {
    for (const Eigen::Vector3d& v : part.vertices) {
      hull->addPoint(toBt(v.cwiseProduct(scale)), false);
    }
  }
  hull->recalcLocalAabb();
  hull->optimizeConvexHull();  // drops the points inside the hull
  if (hull->getNumPoints() > kMaxHullPoints) {
    // btShapeHull samples support points, which include the margin: none while it does.
    // Its fine sampling (highres) keeps round parts round: a 200-facet drum keeps 96
    // points and its radius within 0.5 %, where the coarse one loses 1.2 %.
    hull->setMargin(0);
    btShapeHull reducer(hull.get());
    reducer.buildHull(0, 1);
    auto reduced = std::make_unique<btConvexHullShape>(
        &reducer.getVertexPointer()->getX(), reducer.numVertices(), sizeof(btVector3));
    hull = std::move(reduced);
  }
  hull->setMargin(kHullMarginM);
  // The bounding box is cached with the margin it had when computed (Bullet's default 4 cm
  // until now) and setMargin does not redo it.
  hull->recalcLocalAabb();
  return hull;
}

/// The triangles of `mesh` scaled by `scale` in a bounding-volume tree; the shape owns them.
std::unique_ptr<btCollisionShape> makeStaticTriangleMesh(const TriangleMesh& mesh,
                                                         const Eigen::Vector3d& scale) {
  auto triangles = std::make_unique<btTriangleMesh>();
  for (const MeshPart& part : mesh.parts) {
    for (const auto& t : part.triangles) {
      triangles->addTriangle(toBt(part.vertices[t[0]].cwiseProduct(scale)),
                             toBt(part.vertices[t[1]].cwiseProduct(scale)),
                             toBt(part.vertices[t[2]].cwiseProduct(scale)));
    }
  }
  auto shape = std::make_unique<OwningTriangleMeshShape>(std::move(triangles));
  shape->setMargin(kCollisionMarginM);
  return shape;
}

std::unique_ptr<btCollisionShape> makeMeshShape(const Geometry& geometry, const TriangleMesh* mesh,
                                                Motion motion) {
  if (!mesh) {
    throw std::invalid_argument("mesh '" + geometry.mesh_uri + "' has no triangles to collide");
  }
  if (motion == Motion::Static) return makeStaticTriangleMesh(*mesh, geometry.size);
  return makeConvexHull(*mesh, geometry.size);
}

}  // namespace

std::unique_ptr<btCollisionShape> makeCollisionShape(const Geometry& geometry,
                                                     const TriangleMesh* mesh, Motion motion) {
  switch (geometry.kind) {
    case Geometry::Box: return makeBox(geometry.size);
    case Geometry::Cylinder: return makeCylinder(geometry.size);
    case Geometry::Sphere: return makeSphere(geometry.size.x());
    case Geometry::Plane:
      if (motion != Motion::Static) {
        throw std::invalid_argument("a plane can only be static (Bullet has no moving plane)");
      }
      return std::make_unique<GroundPlaneShape>(toBt(geometry.normal), 0.0);
    case Geometry::Mesh: return makeMeshShape(geometry, mesh, motion);
  }
  throw std::invalid_argument("unknown geometry kind");
}

}  // namespace bullet_sim
