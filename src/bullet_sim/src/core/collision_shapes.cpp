#include "collision_shapes.h"

#include <BulletCollision/CollisionShapes/btShapeHull.h>

#include "bullet_convert.h"

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

template <typename Shape>
std::unique_ptr<btConvexShape> withMargin(std::unique_ptr<Shape> shape) {
  shape->setMargin(kCollisionMarginM);
  return shape;
}

}  // namespace

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
  return hull;
}

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

}  // namespace bullet_sim
