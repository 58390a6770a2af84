#include "render/lens_camera.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "description/gazebo/camera_lens.h"

namespace bullet_sim {
namespace {

/// Rotation taking the face camera's axes to the wide-angle camera's: its +x (optical axis)
/// along ahead, behind, left, right, up and down in turn.
Eigen::Matrix3d faceRotation(int face) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), y = Eigen::Vector3d::UnitY();
  switch (face) {
    case 0: return Eigen::Matrix3d::Identity();
    case 1: return Eigen::AngleAxisd(M_PI, z).matrix();
    case 2: return Eigen::AngleAxisd(M_PI_2, z).matrix();
    case 3: return Eigen::AngleAxisd(-M_PI_2, z).matrix();
    case 4: return Eigen::AngleAxisd(-M_PI_2, y).matrix();
    default: return Eigen::AngleAxisd(M_PI_2, y).matrix();
  }
}

/// The face a direction (camera frame) leaves the cube through: its largest component.
int faceOf(const Eigen::Vector3d& d) {
  Eigen::Index axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  return static_cast<int>(2 * axis) + (d[axis] < 0 ? 1 : 0);
}

sim_render::CameraModel faceModel(const CameraSpec& camera) {
  sim_render::CameraModel model;
  model.width = model.height = camera.lens->env_texture_size;
  model.horizontal_fov_rad = M_PI_2;
  model.clip_near_m = camera.clip_near_m;
  model.clip_far_m = camera.clip_far_m;
  model.validate();
  return model;
}

}  // namespace

LensCamera::LensCamera(const CameraSpec& camera) : width_(camera.width), height_(camera.height) {
  if (!camera.lens) throw std::invalid_argument("camera '" + camera.name + "' has no <lens>");
  for (int i = 0; i < 6; ++i) faces_[i].R_camera_face = faceRotation(i);
  buildSamples(camera);
}

LensCamera::~LensCamera() = default;

void LensCamera::buildSamples(const CameraSpec& camera) {
  const CameraLens lens(*camera.lens, camera.horizontal_fov_rad);
  const sim_render::CameraModel face_model = faceModel(camera);
  const int size = face_model.width;
  const double half_width = 0.5 * width_;
  samples_.assign(static_cast<size_t>(width_) * height_, Sample{});
  for (int row = 0; row < height_; ++row) {
    for (int col = 0; col < width_; ++col) {
      // Image-plane position in half widths, right and up, through the pixel's centre.
      const double x = (col + 0.5 - half_width) / half_width;
      const double y = (0.5 * height_ - row - 0.5) / half_width;
      const double r = std::hypot(x, y);
      const double theta = lens.angle(r);
      if (!(std::abs(theta) <= lens.cutoffRad())) continue;
      const double s = r > 0 ? std::sin(theta) / r : 0.0;
      const Eigen::Vector3d d(std::cos(theta), -s * x, s * y);
      const int face = faceOf(d);
      Eigen::Vector2d uv;
      face_model.project(faces_[face].R_camera_face.transpose() * d, &uv);
      const int u = std::clamp(static_cast<int>(std::floor(uv.x())), 0, size - 1);
      const int v = std::clamp(static_cast<int>(std::floor(uv.y())), 0, size - 1);
      Sample& sample = samples_[static_cast<size_t>(row) * width_ + col];
      sample.face = face;
      sample.offset = 3u * static_cast<std::uint32_t>(v * size + u);
      if (!faces_[face].renderer) {
        faces_[face].renderer = std::make_unique<sim_render::Renderer>(face_model);
      }
    }
  }
}

void LensCamera::render(const sim_render::Scene& scene, const Eigen::Isometry3d& T_world_camera,
                        std::vector<std::uint8_t>& out_rgb8) {
  for (Face& face : faces_) {
    if (!face.renderer) continue;
    Eigen::Isometry3d T_world_face = T_world_camera;
    T_world_face.linear() = T_world_camera.linear() * face.R_camera_face;
    face.renderer->render(scene, T_world_face, face.rgb);
  }
  out_rgb8.resize(samples_.size() * 3);
  for (size_t i = 0; i < samples_.size(); ++i) {
    const Sample& s = samples_[i];
    std::uint8_t* out = &out_rgb8[3 * i];
    if (s.face < 0) {
      out[0] = out[1] = out[2] = 0;
      continue;
    }
    const std::uint8_t* texel = &faces_[s.face].rgb[s.offset];
    out[0] = texel[0], out[1] = texel[1], out[2] = texel[2];
  }
}

int LensCamera::facesRendered() const {
  return static_cast<int>(std::count_if(faces_.begin(), faces_.end(),
                                        [](const Face& f) { return f.renderer != nullptr; }));
}

}  // namespace bullet_sim
