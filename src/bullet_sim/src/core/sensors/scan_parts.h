#ifndef BULLET_SIM_CORE_SCAN_PARTS_H
#define BULLET_SIM_CORE_SCAN_PARTS_H

#include <array>
#include <cstddef>
#include <vector>

#include <btBulletCollisionCommon.h>

namespace bullet_sim {

/// The parts a planar scan can hit, gathered once per scan from Bullet's broadphase (the
/// objects whose bounding boxes lie within range), compounds opened, and each listed for
/// the rays of the directions it covers as seen from the sensor: a ray then tests the few
/// parts in its direction (on the round track 1.5 boxes a ray on average) instead of a
/// walk of the broadphase tree and a slab test of every box whose bounding box it crosses.
/// Boxes are intersected by slabs; every other shape goes to Bullet's narrowphase.
class ScanParts : public btBroadphaseAabbCallback {
 public:
  /// Sample k of the scan looks along azimuth angle_min + k * increment in the sensor frame.
  ScanParts(const btTransform& T_world_sensor, double angle_min, double increment, int samples)
      : T_world_sensor_(T_world_sensor),
        angle_min_(angle_min),
        increment_(increment),
        samples_(samples),
        first_(samples + 1, 0) {}

  /// Lists the objects within `range` of the sensor; false if they make more than
  /// `max_parts` parts, or if the sensor's pose or the range is not finite.
  bool gather(btCollisionWorld& world, double range, size_t max_parts);

  /// Fraction along from -> to (sample `k`) of the nearest hit, or 1 for none.
  double nearestHit(int k, const btVector3& from, const btVector3& to) const;

  bool process(const btBroadphaseProxy* proxy) override;

 private:
  struct Part {
    const btCollisionObject* obj;
    const btCollisionShape* shape;
    btTransform T_world_shape;
    bool box;
    btMatrix3x3 R_shape_world;
    btVector3 half;  ///< a box's half extents, margin included
    btVector3 aabb[2];  ///< its bounding box within the scan's reach: minimum, maximum
  };
  /// A run of rays that meet a part: part, first ray, last ray.
  using Run = std::array<int, 3>;
  /// The azimuths a convex part covers: from `start` counter-clockwise to the largest
  /// `gap` between its corners' azimuths.
  struct Arc {
    double start, gap;
  };

  bool poseIsFinite() const;
  /// Opens the listed objects into parts; false once they make more than `max_parts`.
  bool listParts(size_t max_parts);
  /// Lists each part for the rays of its runs, in ray order.
  void indexRays();
  /// `shape` is not a compound.
  void addShape(const btCollisionObject* obj, const btCollisionShape* shape,
                const btTransform& T_world_shape);
  /// The runs of rays whose azimuths part `p`'s corners span (a box's own corners, any
  /// other shape's bounding box corners): all rays if it surrounds the sensor's axis, none if
  /// it lies wholly above or below the scan plane.
  void addRuns(int p, std::vector<Run>* runs) const;
  /// Part's corners in the sensor frame.
  void sensorCorners(const Part& part, btVector3 corners[8]) const;
  static bool nearScanPlane(const btVector3 corners[8]);
  static bool surroundsAxis(const btVector3 corners[8]);
  static Arc azimuthArc(const btVector3 corners[8]);
  /// The runs of every turn of the azimuths [lo, hi] that meets [angle_min, angle_max].
  void addArcRuns(int p, double lo, double hi, std::vector<Run>* runs) const;

  static constexpr double kPad = 1e-6;  ///< radians and metres kept around each part

  btTransform T_world_sensor_;
  btVector3 reach_min_, reach_max_;  ///< the box around the sensor that every ray stays in
  double angle_min_, increment_;
  int samples_;
  std::vector<const btCollisionObject*> objects_;
  std::vector<Part> parts_;
  std::vector<int> first_;      ///< ray k's parts are ray_parts_[first_[k] .. first_[k + 1])
  std::vector<int> ray_parts_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SCAN_PARTS_H
