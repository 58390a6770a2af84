#include "sim_render/renderer.h"

#include "frame_lights.h"
#include "polygon_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sim_render {
namespace {

// Inward unit normals of the four side planes of the view frustum (camera frame).
struct Frustum {
  double near_m, far_m;
  Eigen::Vector3d sides[4];
};

Frustum makeFrustum(const CameraModel& camera) {
  const double tan_h = camera.cx() / camera.fx();
  const double tan_v = camera.cy() / camera.fy();
  Frustum f;
  f.near_m = camera.clip_near_m;
  f.far_m = camera.clip_far_m;
  f.sides[0] = Eigen::Vector3d(tan_h, -1, 0).normalized();  // left edge:   y <= x tan_h
  f.sides[1] = Eigen::Vector3d(tan_h, 1, 0).normalized();   // right edge:  y >= -x tan_h
  f.sides[2] = Eigen::Vector3d(tan_v, 0, -1).normalized();  // top edge:    z <= x tan_v
  f.sides[3] = Eigen::Vector3d(tan_v, 0, 1).normalized();   // bottom edge: z >= -x tan_v
  return f;
}

bool sphereOutside(const Frustum& f, const Eigen::Vector3d& centre, double radius) {
  if (centre.x() + radius < f.near_m || centre.x() - radius > f.far_m) return true;
  for (const Eigen::Vector3d& side : f.sides) {
    if (side.dot(centre) < -radius) return true;
  }
  return false;
}

bool triangleOutside(const Frustum& f, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     const Eigen::Vector3d& c) {
  for (const Eigen::Vector3d& side : f.sides) {
    if (side.dot(a) < 0 && side.dot(b) < 0 && side.dot(c) < 0) return true;
  }
  return false;
}

using detail::toByte;

}  // namespace

Renderer::Renderer(const CameraModel& camera)
    : camera_(camera), lights_(std::make_unique<detail::FrameLights>()) {
  camera_.validate();
  inverse_depth_.assign(static_cast<std::size_t>(camera_.width) * camera_.height, 0.0f);
}

void Renderer::render(const Scene& scene, const Eigen::Isometry3d& T_world_camera,
                      std::vector<std::uint8_t>& out_rgb8) {
  const std::size_t pixels = static_cast<std::size_t>(camera_.width) * camera_.height;
  out_rgb8.resize(pixels * 3);
  std::fill(inverse_depth_.begin(), inverse_depth_.end(), 0.0f);
  const Lighting& lighting = scene.lighting();
  const std::uint8_t sky[3] = {toByte(lighting.background.x()), toByte(lighting.background.y()),
                               toByte(lighting.background.z())};
  // The first row pixel by pixel, the others copied from it: a row is one memcpy.
  const std::size_t row_bytes = static_cast<std::size_t>(camera_.width) * 3;
  for (std::size_t i = 0; i < row_bytes; i += 3) std::copy(sky, sky + 3, &out_rgb8[i]);
  for (std::size_t offset = row_bytes; offset < pixels * 3; offset += row_bytes) {
    std::copy(out_rgb8.begin(), out_rgb8.begin() + row_bytes, out_rgb8.begin() + offset);
  }

  stats_ = RenderStats();
  const detail::PolygonRasterizer rasterizer(camera_);
  const detail::RasterTarget target{camera_.width, camera_.height, inverse_depth_.data(), out_rgb8.data()};
  const Frustum frustum = makeFrustum(camera_);
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  const double light_norm = lighting.direction.norm();
  const Eigen::Vector3d to_light =
      light_norm > 0 ? Eigen::Vector3d(-lighting.direction / light_norm) : Eigen::Vector3d::Zero();
  lights_->prepare(lighting, T_camera_world);

  // Nearest first (by the far side of a shape's bounding sphere, so that the ground and
  // other large shapes come last): pixels of what lies behind then fail the depth test and
  // are not written twice. Ties keep the scene's order.
  draw_order_.clear();
  const std::vector<SceneShape>& shapes = scene.shapes();
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const Eigen::Vector3d centre = T_camera_world * shapes[i].T_world_shape.translation();
    const double radius = shapes[i].mesh.bounding_radius_m;
    const double key = centre.norm() + radius;
    // A pose that is not finite (a simulation that blew up) has nothing to draw, and a NaN
    // key would break the sort.
    if (!std::isfinite(key) || sphereOutside(frustum, centre, radius)) continue;
    draw_order_.push_back({key, i});
  }
  std::sort(draw_order_.begin(), draw_order_.end());

  for (const std::pair<double, std::size_t>& entry : draw_order_) {
    const SceneShape& shape = shapes[entry.second];
    const Eigen::Isometry3d T_camera_shape = T_camera_world * shape.T_world_shape;
    ++stats_.shapes_drawn;

    const Mesh& mesh = shape.mesh;
    camera_vertices_.resize(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) camera_vertices_[i] = T_camera_shape * mesh.vertices[i];
    const Eigen::Matrix3d R_camera_shape = T_camera_shape.linear();
    const Eigen::Matrix3d R_world_shape = shape.T_world_shape.linear();
    const Texture* texture = shape.spec.texture.get();
    const bool textured = texture && mesh.uvs.size() == mesh.vertices.size();
    // Without coordinates a textured surface shows its texture's mean colour.
    const Eigen::Vector3f colour =
        texture && !textured
            ? Eigen::Vector3f(shape.spec.rgba.head<3>().cwiseProduct(texture->meanColour()))
            : Eigen::Vector3f(shape.spec.rgba.head<3>());
    // The point and spot lights that may reach the shape; each triangle tests these only.
    lights_->selectForShape(T_camera_shape.translation(), mesh.bounding_radius_m);

    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const Eigen::Vector3d& a = camera_vertices_[tri[0]];
      const Eigen::Vector3d& b = camera_vertices_[tri[1]];
      const Eigen::Vector3d& c = camera_vertices_[tri[2]];
      const Eigen::Vector3d normal = R_camera_shape * mesh.face_normals[t];
      if (normal.dot(a) >= 0.0 || triangleOutside(frustum, a, b, c)) continue;

      const Eigen::Vector3d world_normal = R_world_shape * mesh.face_normals[t];
      const double lambert = std::max(0.0, world_normal.dot(to_light));
      Eigen::Vector3f light = lighting.ambient + lighting.diffuse * static_cast<float>(lambert);
      light += lights_->directionalTerm(world_normal);
      const detail::PixelLighting* per_pixel = lights_->onTriangle(a, b, c, normal, light, colour);
      detail::RasterResult result;
      if (textured) {
        detail::TexturedCorners corners;
        corners.texture = texture;
        for (int k = 0; k < 3; ++k) corners.uv[k] = mesh.uvs[tri[k]];
        corners.factor = colour.cwiseProduct(light);
        corners.lighting = per_pixel;
        result = rasterizer.drawTextured(a, b, c, normal, corners, target);
      } else if (per_pixel) {
        result = rasterizer.drawLit(a, b, c, normal, *per_pixel, target);
      } else {
        const std::uint8_t rgb[3] = {toByte(colour.x() * light.x()), toByte(colour.y() * light.y()),
                                     toByte(colour.z() * light.z())};
        result = rasterizer.draw(a, b, c, normal, rgb, target);
      }
      if (result != detail::RasterResult::Culled) ++stats_.triangles_drawn;
      if (result == detail::RasterResult::DrawnClipped) ++stats_.triangles_clipped;
    }
  }
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

double Renderer::depthAt(int col, int row) const {
  if (col < 0 || row < 0 || col >= camera_.width || row >= camera_.height) {
    return std::numeric_limits<double>::infinity();
  }
  const float inverse_depth = inverse_depth_[static_cast<std::size_t>(row) * camera_.width + col];
  return inverse_depth > 0.0f ? 1.0 / inverse_depth : std::numeric_limits<double>::infinity();
}

void Renderer::depthImage(std::vector<float>* depth_m, float above_m, float below_m) const {
  depth_m->resize(inverse_depth_.size());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float* in = inverse_depth_.data();
  float* out = depth_m->data();
  const std::size_t n = inverse_depth_.size();
  // One branch-free pass in float that the compiler vectorises: every pixel is divided (a
  // division inside the condition could not be: it might trap), then selected. Where
  // nothing was drawn the inverse depth is 0 and its depth +inf, which no cutoff passes.
  for (std::size_t i = 0; i < n; ++i) {
    const float d = 1.0f / in[i];
    out[i] = (d > above_m && d < below_m) ? d : nan;
  }
}

}  // namespace sim_render
