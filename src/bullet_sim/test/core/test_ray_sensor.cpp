// A scan cast with the shapes in range listed once for the rays in their directions gives
// the ranges of rays that each walk Bullet's broadphase tree, in worlds of every shape kind
// the simulator builds (boxes, compounds, cylinders, spheres, convex hulls, triangle meshes,
// an endless plane), from level, tilted and upside-down sensors, inside and outside the shapes.
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sensors/ray_sensor.h"

using namespace bullet_sim;

namespace {

/// A Bullet collision world that owns its shapes and objects.
class World {
 public:
  World()
      : dispatcher_(&configuration_),
        world_(&dispatcher_, &broadphase_, &configuration_) {}

  btCollisionShape* keep(btCollisionShape* shape) {
    shapes_.emplace_back(shape);
    return shape;
  }

  void add(btCollisionShape* shape, const btTransform& pose,
           int group = btBroadphaseProxy::DefaultFilter, int mask = btBroadphaseProxy::AllFilter) {
    objects_.push_back(std::make_unique<btCollisionObject>());
    objects_.back()->setCollisionShape(shape);
    objects_.back()->setWorldTransform(pose);
    world_.addCollisionObject(objects_.back().get(), group, mask);
  }

  btCollisionWorld& bullet() {
    world_.updateAabbs();
    return world_;
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btCollisionWorld world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
  std::vector<std::unique_ptr<btTriangleMesh>> meshes_;

 public:
  /// A closed triangle mesh of a cube of side `side` (Bullet's static-mesh shape).
  btCollisionShape* cubeMesh(double side) {
    meshes_.push_back(std::make_unique<btTriangleMesh>());
    const double h = side / 2;
    btVector3 v[8];
    for (int i = 0; i < 8; ++i) v[i] = btVector3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
    const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (const auto& f : faces) meshes_.back()->addTriangle(v[f[0]], v[f[1]], v[f[2]]);
    return keep(new btBvhTriangleMeshShape(meshes_.back().get(), true));
  }
};

btTransform randomPose(std::mt19937_64& rng, double spread) {
  std::uniform_real_distribution<double> position(-spread, spread), unit(-1, 1);
  btQuaternion q(unit(rng), unit(rng), unit(rng), unit(rng) + 1.5);
  q.normalize();
  return btTransform(q, btVector3(position(rng), position(rng), position(rng) * 0.2));
}

/// A cylinder along z as the simulator makes them: one radius (Bullet's cylinder is round
/// with the x half extent as radius, but bounds y by the y half extent).
btCollisionShape* cylinder(World& world, double radius, double half_length) {
  return world.keep(new btCylinderShapeZ(btVector3(radius, radius, half_length)));
}

/// Walls, robots (compounds of boxes and cylinders), posts, balls, a meshed crate, meshed
/// robot parts and the ground, scattered at random within `spread` of the origin.
void fillWorld(World& world, std::mt19937_64& rng, double spread) {
  std::uniform_real_distribution<double> size(0.02, 0.6);
  world.add(world.keep(new btStaticPlaneShape(btVector3(0, 0, 1), -0.3)),
            btTransform::getIdentity());
  for (int i = 0; i < 25; ++i) {
    world.add(world.keep(new btBoxShape(btVector3(size(rng) * 4, size(rng) / 4, size(rng)))),
              randomPose(rng, spread));
  }
  for (int i = 0; i < 6; ++i) {
    auto* compound = static_cast<btCompoundShape*>(world.keep(new btCompoundShape(false)));
    compound->addChildShape(randomPose(rng, 0.1),
                            world.keep(new btBoxShape(btVector3(size(rng), size(rng), size(rng)))));
    compound->addChildShape(randomPose(rng, 0.1), cylinder(world, size(rng), size(rng)));
    auto* inner = static_cast<btCompoundShape*>(world.keep(new btCompoundShape(false)));
    inner->addChildShape(randomPose(rng, 0.1),
                         world.keep(new btBoxShape(btVector3(size(rng), size(rng), size(rng)))));
    compound->addChildShape(randomPose(rng, 0.2), inner);
    world.add(compound, randomPose(rng, spread));
  }
  for (int i = 0; i < 5; ++i) {
    world.add(cylinder(world, size(rng) / 3, size(rng)),
              randomPose(rng, spread));
    world.add(world.keep(new btSphereShape(size(rng) / 2)), randomPose(rng, spread));
  }
  world.add(world.cubeMesh(0.5), randomPose(rng, spread));
  // A robot link's mesh becomes a convex hull.
  for (int i = 0; i < 3; ++i) {
    auto* hull = static_cast<btConvexHullShape*>(world.keep(new btConvexHullShape()));
    std::uniform_real_distribution<double> coordinate(-0.3, 0.3);
    for (int v = 0; v < 12; ++v) {
      hull->addPoint(btVector3(coordinate(rng), coordinate(rng), coordinate(rng)), false);
    }
    hull->recalcLocalAabb();
    world.add(hull, randomPose(rng, spread));
  }
  // Seen by no ray (the simulator adds links without collisions this way).
  world.add(world.keep(new btBoxShape(btVector3(5, 5, 5))), btTransform::getIdentity(), 0, 0);
}

RaySpec lidar(double min_angle, double max_angle, int samples) {
  RaySpec spec;
  spec.min_angle_rad = min_angle;
  spec.max_angle_rad = max_angle;
  spec.samples = samples;
  spec.range_min_m = 0.12;
  spec.range_max_m = 3.5;
  return spec;
}

Eigen::Isometry3d toEigenPose(const btTransform& T) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const btQuaternion q = T.getRotation();
  pose.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(T.getOrigin().x(), T.getOrigin().y(), T.getOrigin().z());
  return pose;
}

/// Casts `spec` from `pose` both ways; returns how many rays hit.
int expectSameScan(btCollisionWorld& world, const Eigen::Isometry3d& pose, const RaySpec& spec) {
  std::mt19937_64 rng_listed(1), rng_walked(1);
  LaserScanData listed, walked;
  castScan(world, pose, spec, &rng_listed, &listed);
  castScan(world, pose, spec, &rng_walked, &walked, 0);
  EXPECT_EQ(listed.ranges.size(), static_cast<size_t>(spec.samples));
  EXPECT_EQ(listed.ranges.size(), walked.ranges.size());
  int hits = 0;
  for (size_t i = 0; i < listed.ranges.size() && i < walked.ranges.size(); ++i) {
    if (std::isinf(walked.ranges[i])) {
      EXPECT_TRUE(std::isinf(listed.ranges[i])) << "ray " << i << " reads " << listed.ranges[i];
      continue;
    }
    ++hits;
    EXPECT_NEAR(listed.ranges[i], walked.ranges[i], 1e-6) << "ray " << i;
  }
  return hits;
}

}  // namespace

/// Seeds of the random worlds; the world's spread (1 to 5 m) and the poses come from the seed.
class ScanPartsInWorld : public ::testing::TestWithParam<int> {};
INSTANTIATE_TEST_SUITE_P(Seeded, ScanPartsInWorld, ::testing::Range(1, 13));

TEST_P(ScanPartsInWorld, ListedRaysReadWhatRaysWalkingTheBroadphaseRead) {
  std::mt19937_64 rng(GetParam());
  World world;
  fillWorld(world, rng, 1.0 + GetParam() % 5);
  const std::vector<RaySpec> specs = {lidar(0.0, 6.28319, 360), lidar(-1.5, 1.5, 101),
                                      lidar(2.0, 9.0, 250), lidar(0.3, 0.3, 1)};
  int hits = 0, rays = 0;
  for (int pose = 0; pose < 60; ++pose) {
    // Level sensors first, then tilted ones, then any orientation.
    btTransform T = randomPose(rng, 2.5);
    if (pose < 20) T.setRotation(btQuaternion(btVector3(0, 0, 1), pose * 0.7));
    if (pose >= 20 && pose < 40) {
      T.setRotation(btQuaternion(btVector3(0, 0, 1), pose) *
                    btQuaternion(btVector3(1, 0, 0), 0.05 * (pose - 30)));
    }
    for (const RaySpec& spec : specs) {
      hits += expectSameScan(world.bullet(), toEigenPose(T), spec);
      rays += spec.samples;
    }
  }
  // The worlds are dense enough that most rays hit something, and not all.
  EXPECT_GT(hits, rays / 3);
  EXPECT_LT(hits, rays);
}

TEST(ScanParts, ASensorInsideABoxOrOnAnEdgeReadsTheSameBothWays) {
  World world;
  world.add(world.keep(new btBoxShape(btVector3(0.5, 0.5, 0.5))), btTransform::getIdentity());
  world.add(world.keep(new btBoxShape(btVector3(0.2, 0.2, 0.2))),
            btTransform(btQuaternion::getIdentity(), btVector3(2, 0, 0)));
  const RaySpec spec = lidar(-M_PI, M_PI, 181);
  for (const Eigen::Vector3d& at : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.8, 0.2, 0.2),
                                    Eigen::Vector3d(1.8, 0.0, 0.0), Eigen::Vector3d(0.5, 0.5, 0)}) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = at;
    expectSameScan(world.bullet(), pose, spec);
  }
  // From the box's centre every ray starts inside it: all read range_min (to float precision).
  std::mt19937_64 rng(1);
  LaserScanData scan;
  castScan(world.bullet(), Eigen::Isometry3d::Identity(), spec, &rng, &scan);
  for (const float r : scan.ranges) EXPECT_NEAR(r, spec.range_min_m, 1e-6);
}

TEST(ScanParts, ABoxBeyondReachOrBesideTheScanPlaneIsNotSeenAndOneWithinIs) {
  World world;
  // Centred 0.5 m above the sensor's plane (half height 0.4), 1 m ahead: not seen.
  world.add(world.keep(new btBoxShape(btVector3(0.1, 0.1, 0.4))),
            btTransform(btQuaternion::getIdentity(), btVector3(1, 0, 0.5)));
  // 3.6 m to the left, beyond range_max 3.5 m: not seen.
  world.add(world.keep(new btBoxShape(btVector3(0.1, 0.1, 0.1))),
            btTransform(btQuaternion::getIdentity(), btVector3(0, 3.7, 0)));
  // Behind: its near face 2 m away.
  world.add(world.keep(new btBoxShape(btVector3(0.1, 0.1, 0.1))),
            btTransform(btQuaternion::getIdentity(), btVector3(-2.1, 0, 0)));
  const RaySpec spec = lidar(-M_PI, M_PI, 361);  // ray 180 looks along +x, 270 along +y
  std::mt19937_64 rng(1);
  LaserScanData scan;
  castScan(world.bullet(), Eigen::Isometry3d::Identity(), spec, &rng, &scan);
  EXPECT_TRUE(std::isinf(scan.ranges[180]));
  EXPECT_TRUE(std::isinf(scan.ranges[270]));
  EXPECT_NEAR(scan.ranges[0], 2.0, 1e-6);
  EXPECT_NEAR(scan.ranges[360], 2.0, 1e-6);
  // Lowered by 0.15 m the first box reaches the plane (its bottom at -0.05 m).
  Eigen::Isometry3d raised = Eigen::Isometry3d::Identity();
  raised.translation().z() = 0.15;
  castScan(world.bullet(), raised, spec, &rng, &scan);
  EXPECT_NEAR(scan.ranges[180], 0.9, 1e-6);
}

TEST(ScanParts, ASensorPoseThatIsNotFiniteSeesNothingEitherWay) {
  std::mt19937_64 rng(3);
  World world;
  fillWorld(world, rng, 2.5);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expectSameScan(world.bullet(), pose, lidar(0.0, 6.28319, 360)), 0);
  pose = Eigen::Isometry3d::Identity();
  pose.linear()(0, 0) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(expectSameScan(world.bullet(), pose, lidar(0.0, 6.28319, 360)), 0);
  // The same sensor at the origin, level, sees the world (checks the fixture).
  const Eigen::Isometry3d level = Eigen::Isometry3d::Identity();
  EXPECT_GT(expectSameScan(world.bullet(), level, lidar(0.0, 6.28319, 360)), 0);
}

TEST(ScanParts, AScanThatWouldWalkTheBroadphaseIsNotCastWhenWalksAreRefused) {
  World world;
  world.add(world.keep(new btBoxShape(btVector3(0.2, 0.2, 0.2))),
            btTransform(btQuaternion::getIdentity(), btVector3(1, 0, 0)));
  RaySpec spec = lidar(-M_PI, M_PI, 90);
  spec.noise_stddev_m = 0.01;
  const Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::mt19937_64 rng(7), untouched(7);
  LaserScanData scan;
  // No part may be listed (0): every ray would walk the broadphase.
  EXPECT_FALSE(castScan(world.bullet(), pose, spec, &rng, &scan, 0, /*may_walk=*/false));
  EXPECT_TRUE(scan.ranges.empty());
  EXPECT_TRUE(rng == untouched);
  // Listed, it is cast as with walks allowed, noise and all.
  std::mt19937_64 rng_refused(7), rng_allowed(7);
  LaserScanData refused, allowed;
  EXPECT_TRUE(castScan(world.bullet(), pose, spec, &rng_refused, &refused, kMaxListedScanParts,
                       /*may_walk=*/false));
  EXPECT_TRUE(castScan(world.bullet(), pose, spec, &rng_allowed, &allowed));
  EXPECT_EQ(refused.ranges, allowed.ranges);
  // The box's near face is 0.8 m ahead.
  EXPECT_NEAR(refused.ranges[45], 0.8, 0.05);
}
