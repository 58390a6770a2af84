#include "frame_lights.h"

#include <algorithm>
#include <cmath>

namespace sim_render {
namespace detail {
namespace {

bool usable(const LocalLight& light) {
  return light.position.allFinite() && light.direction.allFinite() &&
         light.direction.norm() > 0 && light.diffuse.allFinite() && light.range_m > 0 &&
         std::isfinite(light.constant) && std::isfinite(light.linear) &&
         std::isfinite(light.quadratic) && std::isfinite(light.spot_inner_rad) &&
         std::isfinite(light.spot_outer_rad) && std::isfinite(light.spot_falloff);
}

}  // namespace

void FrameLights::prepare(const Lighting& lighting, const Eigen::Isometry3d& T_camera_world) {
  camera_lights_.clear();
  directional_lights_.clear();
  for (const LocalLight& light : lighting.lights) {
    if (!usable(light)) continue;
    if (light.kind == LocalLight::Kind::Directional) {
      directional_lights_.push_back({Eigen::Vector3d(-light.direction.normalized()), light.diffuse});
    } else {
      camera_lights_.push_back(cameraLight(light, T_camera_world));
    }
  }
}

FrameLights::CameraLight FrameLights::cameraLight(const LocalLight& light,
                                                  const Eigen::Isometry3d& T_camera_world) {
  CameraLight c;
  c.position = T_camera_world * light.position;
  c.axis = T_camera_world.linear() * light.direction.normalized();
  c.range_m = std::min(light.range_m, 1e15);
  const bool spot = light.kind == LocalLight::Kind::Spot;
  c.outer_half_rad = spot ? 0.5 * light.spot_outer_rad : M_PI;
  PixelLight& p = c.pixel;
  p.x = static_cast<float>(c.position.x());
  p.y = static_cast<float>(c.position.y());
  p.z = static_cast<float>(c.position.z());
  p.axis_x = static_cast<float>(c.axis.x());
  p.axis_y = static_cast<float>(c.axis.y());
  p.axis_z = static_cast<float>(c.axis.z());
  p.r = light.diffuse.x();
  p.g = light.diffuse.y();
  p.b = light.diffuse.z();
  p.range_squared = static_cast<float>(c.range_m * c.range_m);
  p.constant = static_cast<float>(light.constant);
  p.linear = static_cast<float>(light.linear);
  p.quadratic = static_cast<float>(light.quadratic);
  p.spot = spot;
  // OGRE's spotlight_params: the cosines of the half angles.
  const double cos_inner = std::cos(0.5 * light.spot_inner_rad);
  const double cos_outer = std::cos(c.outer_half_rad);
  p.cos_outer_half = static_cast<float>(cos_outer);
  // Inner and outer cones alike (or crossed): the outer cone is a hard edge.
  p.inverse_cone =
      cos_inner > cos_outer ? static_cast<float>(1.0 / (cos_inner - cos_outer)) : 1e30f;
  p.falloff = static_cast<float>(light.spot_falloff);
  p.plane_distance = 0.0f;
  return c;
}

bool FrameLights::reaches(const CameraLight& light, const Eigen::Vector3d& centre,
                          double radius_m) {
  const Eigen::Vector3d to_centre = centre - light.position;
  const double distance = to_centre.norm();
  if (distance - radius_m > light.range_m) return false;
  if (!light.pixel.spot || distance <= radius_m) return true;
  const double off_axis = std::acos(std::clamp(light.axis.dot(to_centre) / distance, -1.0, 1.0));
  return off_axis - std::asin(radius_m / distance) <= light.outer_half_rad;
}

void FrameLights::selectForShape(const Eigen::Vector3d& centre, double radius_m) {
  shape_lights_.clear();
  for (const CameraLight& light : camera_lights_) {
    if (reaches(light, centre, radius_m)) shape_lights_.push_back(&light);
  }
}

Eigen::Vector3f FrameLights::directionalTerm(const Eigen::Vector3d& normal) const {
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (const DirectionalLight& d : directional_lights_) {
    sum += d.diffuse * static_cast<float>(std::max(0.0, normal.dot(d.to_light)));
  }
  return sum;
}

const PixelLighting* FrameLights::onTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                             const Eigen::Vector3d& c,
                                             const Eigen::Vector3d& normal,
                                             const Eigen::Vector3f& base,
                                             const Eigen::Vector3f& colour) {
  if (shape_lights_.empty()) return nullptr;
  triangle_lights_.clear();
  const Eigen::Vector3d centre = (a + b + c) / 3.0;
  const double radius = std::sqrt(std::max(
      {(a - centre).squaredNorm(), (b - centre).squaredNorm(), (c - centre).squaredNorm()}));
  for (const CameraLight* light : shape_lights_) {
    // The light's height above the triangle's plane: n . L > 0 over the whole triangle
    // only when it is in front, and no point of it is nearer than that.
    const double height = normal.dot(light->position - a);
    if (!(height > 0.0) || height > light->range_m || !reaches(*light, centre, radius)) continue;
    triangle_lights_.push_back(light->pixel);
    triangle_lights_.back().plane_distance = static_cast<float>(height);
  }
  if (triangle_lights_.empty()) return nullptr;
  pixel_lighting_.lights = triangle_lights_.data();
  pixel_lighting_.count = static_cast<int>(triangle_lights_.size());
  pixel_lighting_.base = base;
  pixel_lighting_.colour = colour;
  return &pixel_lighting_;
}

}  // namespace detail
}  // namespace sim_render
