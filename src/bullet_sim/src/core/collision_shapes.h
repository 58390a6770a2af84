#ifndef BULLET_SIM_CORE_COLLISION_SHAPES_H
#define BULLET_SIM_CORE_COLLISION_SHAPES_H

#include <memory>

#include <btBulletCollisionCommon.h>
#include <Eigen/Core>

#include "bullet_sim/mesh.h"

namespace bullet_sim {

/// Collision margin of every shape: Bullet's default 4 cm would swell the Burger's
/// millimetre parts. Boxes, cylinders and spheres keep it inside their size.
constexpr double kCollisionMarginM = 0.0005;

/// A box of full size x y z centred on its frame.
std::unique_ptr<btConvexShape> makeBox(const Eigen::Vector3d& size);
/// A cylinder along z: size r r length.
std::unique_ptr<btConvexShape> makeCylinder(const Eigen::Vector3d& size);
/// A sphere of radius `radius_m`.
std::unique_ptr<btConvexShape> makeSphere(double radius_m);

/// Margin of convex hulls. Bullet adds it outside a hull (a primitive keeps it inside its
/// size), so it is kept small: 0.5 mm on a 33 mm wheel would make it roll 1.5 % too far.
constexpr double kHullMarginM = 0.0001;

/// Largest number of points a mesh's convex hull keeps (a wheel of up to 128 facets keeps
/// all); larger hulls are reduced with btShapeHull's fine sampling to support points on the
/// hull (TurtleBot3's tire: 2971 points to 224), which keeps contacts cheap.
constexpr int kMaxHullPoints = 256;

/// The convex hull of every vertex of `mesh` scaled by `scale`, for moving bodies: Bullet
/// has no reliable contact between two triangle meshes, and a triangle mesh on a moving
/// body is slow and lets thin parts tunnel.
std::unique_ptr<btConvexHullShape> makeConvexHull(const TriangleMesh& mesh,
                                                  const Eigen::Vector3d& scale);

/// The triangles of `mesh` scaled by `scale` in a bounding-volume tree, for static bodies
/// (walls, furniture): concave shapes are kept as they are. The shape owns its triangles.
std::unique_ptr<btCollisionShape> makeStaticTriangleMesh(const TriangleMesh& mesh,
                                                         const Eigen::Vector3d& scale);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_COLLISION_SHAPES_H
