#ifndef BULLET_SIM_TYPES_H
#define BULLET_SIM_TYPES_H

#include <Eigen/Geometry>

#include <string>

namespace bullet_sim {

/// A rigid transform: position in metres and a unit quaternion.
struct Pose3 {
  Eigen::Vector3d position{0, 0, 0};
  Eigen::Quaterniond orientation{1, 0, 0, 0};
};

/// Linear (m/s) and angular (rad/s) velocity, expressed in the world frame.
struct Twist3 {
  Eigen::Vector3d linear{0, 0, 0};
  Eigen::Vector3d angular{0, 0, 0};
};

/// The image a surface is painted with and how its texture coordinates are mapped:
/// uv' = uv_scale * uv + uv_offset (an OGRE texture_unit's `scale` and `scroll`).
struct TextureRef {
  std::string path;  ///< the image file; empty: no texture
  Eigen::Vector2f uv_scale{1.0f, 1.0f};
  Eigen::Vector2f uv_offset{0.0f, 0.0f};
};

/// Bullet's constraint solver settings that can be changed while running
/// (btContactSolverInfo: Bullet's defaults). get/set_physics_properties show them in ODE's
/// fields: sor_pgs_iters, sor_pgs_w, erp, cfm.
struct SolverSettings {
  int iterations = 10;  ///< solver iterations per step (>= 1)
  double sor = 1.0;     ///< successive over-relaxation factor (> 0)
  double erp = 0.2;     ///< error reduction of joints and deep contacts, [0, 1]
  double cfm = 0.0;     ///< constraint force mixing added to every constraint (>= 0)
  bool operator==(const SolverSettings& o) const {
    return iterations == o.iterations && sor == o.sor && erp == o.erp && cfm == o.cfm;
  }
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_TYPES_H
