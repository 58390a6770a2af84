// The round-track world and an approximate Burger, built from the figures in
// /work/shared/DESIGN.md; shared by the tests and the benchmark.
#pragma once

#include "sim_render/scene.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace sim_render {
namespace round_track {

constexpr double kWallThickness_m = 0.015;
constexpr double kWallHeight_m = 0.5;
constexpr double kSpawnYaw_rad = 1.5675;
constexpr double kBaseLinkHeight_m = 0.010;

/// Wall centres: x, y, yaw, length (DESIGN.md).
constexpr std::array<std::array<double, 4>, 21> kWalls = {{
    {1.53496, 2.894504, 0.736056, 1.0},   {2.04294, 2.386858, 0.881268, 0.5},
    {3.72582, 2.23758, 1.57177, 3.0},     {0.196982, 3.258921, 1.57467, 2.0},
    {5.21431, 0.73692, -0.000378, 3.0},   {3.8664, -2.46629, -1.1525, 0.5},
    {5.13135, -0.99504, -0.334721, 0.5},  {4.92558, -1.45102, -0.501603, 0.5},
    {4.2862, -2.20397, -0.858577, 0.5},   {3.41064, -2.6531, 1.9485, 0.5},
    {-0.80941, 0.25461, 0, 6.0},          {4.63833, -1.85451, 2.40733, 0.5},
    {1.1918, -2.74499, 1.5735, 4.0},      {0.54193, 0.34703, 0, 3.8},
    {0.87641, 1.88745, 0.736056, 1.0},    {1.4037, 1.35442, 0.881268, 0.5},
    {2.78265, 1.19568, 1.57177, 2.4},     {3.98336, 0.09495, -0.000378, 2.2},
    {1.89949, -1.53786, 1.5735, 2.7},     {3.43608, -1.41841, 2.08925, 0.5},
    {3.79555, -1.15857, -0.858577, 0.5},
}};

inline const Eigen::Vector4f kWallColour(0.57f, 0.417f, 0.25f, 1.0f);
inline const Eigen::Vector4f kGroundColour(0.5f, 0.5f, 0.5f, 1.0f);
inline const Eigen::Vector4f kWhite(1.0f, 1.0f, 1.0f, 1.0f);

/// Start line: box 0.015 x 1.5 x 0.015 at (-0.1, 0.333, 0.022), yaw 1.5687.
inline const Eigen::Vector3d kStartLineSize(0.015, 1.5, 0.015);

inline Eigen::Isometry3d pose(double x, double y, double z, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

inline Eigen::Isometry3d startLinePose() { return pose(-0.1, 0.333, 0.022, 1.5687); }

/// Base link of a robot standing at (x, y) with heading yaw.
inline Eigen::Isometry3d baseLinkPose(double x, double y, double yaw) {
  return pose(x, y, kBaseLinkHeight_m, yaw);
}

/// camera_link = base_link + (0.02, 0, 0.295), no rotation.
inline Eigen::Isometry3d cameraPose(const Eigen::Isometry3d& T_world_base) {
  return T_world_base * pose(0.02, 0, 0.295, 0);
}

/// Ground (100 x 100 m plane), the 21 walls and the start line, with the world's light.
inline ShapeId addWorld(Scene& scene) {
  scene.lighting().direction = Eigen::Vector3d(-0.5, 0.1, -0.9);
  scene.lighting().diffuse = Eigen::Vector3f(0.8f, 0.8f, 0.8f);
  scene.lighting().ambient = Eigen::Vector3f(0.4f, 0.4f, 0.4f);
  scene.lighting().background = Eigen::Vector3f(0.7f, 0.7f, 0.7f);
  scene.add(ShapeSpec::plane(100, 100, kGroundColour), Eigen::Isometry3d::Identity());
  for (const auto& w : kWalls) {
    scene.add(ShapeSpec::box(kWallThickness_m, w[3], kWallHeight_m, kWallColour),
              pose(w[0], w[1], 0.5 * kWallHeight_m, w[2]));
  }
  return scene.add(ShapeSpec::box(kStartLineSize.x(), kStartLineSize.y(), kStartLineSize.z(), kWhite),
                   startLinePose());
}

/// About thirty primitives shaped like the Burger with its poles, camera and flag, placed
/// relative to base_link. Returns how many shapes were added.
inline int addRobot(Scene& scene, const Eigen::Isometry3d& T_world_base) {
  const Eigen::Vector4f dark(0.3f, 0.3f, 0.3f, 1), light_black(0.4f, 0.4f, 0.4f, 1);
  const Eigen::Vector4f orange(1.0f, 0.42f, 0.04f, 1), black(0, 0, 0, 1);
  const Eigen::Isometry3d wheel_tilt(Eigen::AngleAxisd(-1.57, Eigen::Vector3d::UnitX()));
  int count = 0;
  auto add = [&](const ShapeSpec& spec, const Eigen::Isometry3d& T_base_shape) {
    scene.add(spec, T_world_base * T_base_shape);
    ++count;
  };
  for (double z : {0.0, 0.056, 0.115}) add(ShapeSpec::box(0.105, 0.105, 0.006, dark), pose(-0.032, 0, z, 0));
  for (double x : {-0.08, 0.016}) {
    for (double y : {-0.046, 0.046}) {
      for (double z : {0.028, 0.0855}) add(ShapeSpec::cylinder(0.004, 0.05, light_black), pose(x, y, z, 0));
    }
  }
  add(ShapeSpec::box(0.088, 0.068, 0.035, dark), pose(-0.042, 0, 0.0245, 0));
  for (double y : {-0.046, 0.046}) add(ShapeSpec::box(0.046, 0.028, 0.034, light_black), pose(0, y, 0.023, 0));
  for (double y : {-0.08, 0.08}) {
    add(ShapeSpec::cylinder(0.033, 0.018, black), pose(0, y, 0.023, 0) * wheel_tilt);
    add(ShapeSpec::box(0.046, 0.008, 0.019, light_black), pose(0, y, 0.023, 0) * wheel_tilt);
  }
  add(ShapeSpec::box(0.030, 0.009, 0.020, black), pose(-0.081, 0, -0.004, 0) * wheel_tilt);
  add(ShapeSpec::cylinder(0.036, 0.025, dark), pose(-0.032, 0, 0.1515, 0));
  add(ShapeSpec::cylinder(0.030, 0.016, black), pose(-0.032, 0, 0.172, 0));
  add(ShapeSpec::cylinder(0.055, 0.0315, dark), pose(-0.017, 0, 0.1655, 0));
  for (double y : {-0.064, 0.064}) add(ShapeSpec::cylinder(0.003, 0.09, light_black), pose(-0.008, y, 0.18, 0));
  add(ShapeSpec::box(0.062, 0.135, 0.01, dark), pose(-0.016, 0, 0.23, 0));
  add(ShapeSpec::box(0.015, 0.035, 0.02, black), pose(0.02, 0, 0.295, 0));
  add(ShapeSpec::cylinder(0.004, 0.055, black), pose(0.01, 0, 0.2625, 0));
  add(ShapeSpec::cylinder(0.003, 0.3, light_black), pose(-0.03, 0, 0.39, 0));
  add(ShapeSpec::box(0.1, 0.002, 0.06, orange), pose(-0.08, 0, 0.51, 0));
  add(ShapeSpec::sphere(0.008, orange), pose(-0.03, 0, 0.545, 0));
  return count;
}

}  // namespace round_track
}  // namespace sim_render
