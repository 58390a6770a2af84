#ifndef BULLET_SIM_CORE_COLLISION_SHAPES_H
#define BULLET_SIM_CORE_COLLISION_SHAPES_H

#include <memory>

#include <btBulletCollisionCommon.h>
#include <Eigen/Core>

#include "bullet_sim/description/mesh.h"
#include "bullet_sim/description/robot_spec.h"

namespace bullet_sim {

/// Collision margin of every shape: Bullet's default 4 cm would swell the Burger's
/// millimetre parts. Boxes, cylinders and spheres keep it inside their size.
constexpr double kCollisionMarginM = 0.0005;

/// Margin of convex hulls. Bullet adds it outside a hull (a primitive keeps it inside its
/// size), so it is kept small: 0.5 mm on a 33 mm wheel would make it roll 1.5 % too far.
constexpr double kHullMarginM = 0.0001;

/// Largest number of points a mesh's convex hull keeps (a wheel of up to 128 facets keeps
/// all); larger hulls are reduced with btShapeHull's fine sampling to support points on the
/// hull (TurtleBot3's tire: 2971 points to 224), which keeps contacts cheap.
constexpr int kMaxHullPoints = 256;

/// How far above a ground plane its bounding box reaches: parts nearer than this are tested
/// for contact every step.
constexpr double kGroundSlabM = 0.01;

/// What a shape is attached to: a static shape never moves (a world wall), a moving one is
/// part of a dynamic body (a robot link).
enum class Motion { Static, Moving };

/// The Bullet collision shape of `geometry`, centred on its frame; the one place a shape is
/// made from a description. Boxes, cylinders (along z) and spheres are Bullet's primitives
/// with their margin inside their size. A mesh (`mesh` holds its triangles, scaled by
/// geometry.size) is, on a moving body, the convex hull of its vertices, reduced to at most
/// kMaxHullPoints: Bullet has no reliable contact between two triangle meshes, and a
/// triangle mesh on a moving body is slow and lets thin parts tunnel. On a static body it is
/// the triangles themselves in a bounding-volume tree, so concave shapes keep their shape. A
/// plane (static only) is infinite, its bounding box cut kGroundSlabM above the surface when
/// its normal is a world axis, so that parts well above the ground are not tested.
/// @throws std::invalid_argument for a mesh without triangles or a moving plane.
std::unique_ptr<btCollisionShape> makeCollisionShape(const Geometry& geometry,
                                                     const TriangleMesh* mesh, Motion motion);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_COLLISION_SHAPES_H
