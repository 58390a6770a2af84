#include "bullet_sim/render/camera_renderer.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include <sim_render/renderer.h>

#include "bullet_sim/errors.h"
#include "bullet_sim/render/depth_camera.h"
#include "description/gazebo/camera_lens.h"
#include "description/robot_plan.h"
#include "render/camera_effects.h"
#include "render/lens_camera.h"
#include "render/scene_lights.h"
#include "render/shape_sources.h"
#include "sensors/sensor_schedule.h"

namespace bullet_sim {
namespace {

std::string cameraName(const CameraSpec& camera) {
  return "camera '" + camera.name + "' on link '" + camera.link + "'";
}

/// The pinhole model of a camera; for a wide-angle one, a pinhole with the same image and
/// clip distances, the lens's focal length set by the caller.
sim_render::CameraModel cameraModel(const CameraSpec& camera) {
  sim_render::CameraModel model;
  model.width = camera.width;
  model.height = camera.height;
  model.horizontal_fov_rad = camera.lens ? M_PI_2 : camera.horizontal_fov_rad;
  model.clip_near_m = camera.clip_near_m;
  model.clip_far_m = camera.clip_far_m;
  return model;
}

/// A wide-angle camera's lens maps its hfov and its cube faces can be rendered.
void validateLens(const CameraSpec& camera) {
  if (camera.depth) throw std::invalid_argument("a wide-angle camera has no depth");
  CameraLens(*camera.lens, camera.horizontal_fov_rad);
  const int size = camera.lens->env_texture_size;
  if (!(size >= 4 && size <= 2048)) {
    throw std::invalid_argument("<lens> <env_texture_size>: " + std::to_string(size) +
                                " is not a pixel count in 4..2048");
  }
}

/// World pose of `link` among `poses`; `hint` remembers where it was last time, since the
/// simulation lists the links in the same order on every call.
const Pose3* findLink(const std::vector<LinkPose>& poses, const std::string& link, size_t* hint) {
  if (*hint < poses.size() && poses[*hint].link == link) return &poses[*hint].pose;
  for (size_t i = 0; i < poses.size(); ++i) {
    if (poses[i].link == link) {
      *hint = i;
      return &poses[i].pose;
    }
  }
  return nullptr;
}

void toMono(const std::vector<uint8_t>& rgb, std::vector<uint8_t>* mono) {
  mono->resize(rgb.size() / 3);
  for (size_t i = 0; i < mono->size(); ++i) {
    const double y = 0.299 * rgb[3 * i] + 0.587 * rgb[3 * i + 1] + 0.114 * rgb[3 * i + 2];
    (*mono)[i] = static_cast<uint8_t>(std::lround(std::min(255.0, y)));
  }
}

/// Camera `index` of `robot` (spec `spec`), checked to exist and, when a depth image is
/// asked for, to be a depth camera.
const CameraSpec& cameraToRender(const RobotSpec& spec, const std::string& robot, size_t index,
                                 bool with_depth) {
  if (index >= spec.cameras.size()) {
    throw std::out_of_range("robot '" + robot + "' has no camera " + std::to_string(index) +
                            " (it has " + std::to_string(spec.cameras.size()) + ")");
  }
  const CameraSpec& camera = spec.cameras[index];
  if (with_depth && !camera.depth) {
    throw std::invalid_argument(cameraName(camera) + " of robot '" + robot +
                                "' is not a depth camera");
  }
  return camera;
}

/// Everything of `image` but its pixels and step.
void setImageHeader(const CameraSpec& camera, double time_s, ImageData* image) {
  image->time_s = time_s;
  image->frame_id = camera.frame_id;
  image->width = camera.width;
  image->height = camera.height;
  image->encoding = imageEncoding(camera);
}

/// The depth buffer of the pass `renderer` just drew, its cutoffs applied.
void readDepth(const sim_render::Renderer& renderer, const CameraSpec& camera, double time_s,
               DepthImageData* depth) {
  depth->time_s = time_s;
  depth->frame_id = camera.frame_id;
  depth->width = camera.width;
  depth->height = camera.height;
  renderer.depthImage(&depth->depth_m, static_cast<float>(camera.depth->cutoff_m),
                      static_cast<float>(camera.depth->cutoff_max_m));
}

/// The pixels of `image` in its encoding (mono8 or bgr8) from an rgb8 frame, and its step.
void encodeFromRgb(const std::vector<uint8_t>& rgb, int width, ImageData* image) {
  if (image->encoding == "mono8") {
    toMono(rgb, &image->data);
    image->step = width;
    return;
  }
  image->data.resize(rgb.size());
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    image->data[i] = rgb[i + 2];
    image->data[i + 1] = rgb[i + 1];
    image->data[i + 2] = rgb[i];
  }
  image->step = 3 * width;
}

/// Two frames of one camera would be drawn with the same buffers at once.
void requireDistinctCameras(const std::vector<CameraFrame>& frames) {
  std::set<std::pair<std::string, size_t>> named;
  for (const CameraFrame& frame : frames) {
    if (!named.insert({frame.robot, frame.index}).second) {
      throw std::invalid_argument("renderTogether: camera " + std::to_string(frame.index) +
                                  " of robot '" + frame.robot + "' named twice");
    }
  }
}

}  // namespace

std::string imageEncoding(const CameraSpec& camera) {
  if (camera.format == "R8G8B8") return "rgb8";
  if (camera.format == "B8G8R8") return "bgr8";
  if (camera.format == "L8") return "mono8";
  if (camera.format == "R16G16B16") return "rgb16";
  if (camera.format == "L16") return "mono16";
  throw LoadError(cameraName(camera) + ": <image><format> '" + camera.format +
                  "' is not supported (R8G8B8, B8G8R8, L8, R16G16B16 or L16)");
}

void validateCamera(const CameraSpec& camera) {
  try {
    cameraModel(camera).validate();
    if (camera.lens) validateLens(camera);
  } catch (const std::invalid_argument& e) {
    throw LoadError(cameraName(camera) + ": " + e.what());
  }
  imageEncoding(camera);
}

CameraInfoData cameraInfo(const CameraSpec& camera, double time_s) {
  const sim_render::CameraModel model = cameraModel(camera);
  CameraInfoData info;
  info.time_s = time_s;
  info.frame_id = camera.frame_id;
  info.width = camera.width;
  info.height = camera.height;
  info.K = model.K();
  info.P = model.P();
  if (camera.lens) {
    const double f_px = CameraLens(*camera.lens, camera.horizontal_fov_rad).paraxialFocalPx(
        camera.width);
    info.K[0] = info.K[4] = info.P[0] = info.P[5] = f_px;
  }
  info.D = camera.info_distortion;
  info.P[3] = -info.P[0] * camera.hack_baseline_m;
  return info;
}

struct CameraRenderer::Impl {
  /// A robot visual in the scene and the link that carries it.
  struct Visual {
    std::string link;
    size_t link_hint = 0;
    Eigen::Isometry3d T_link_visual;
    sim_render::ShapeId id = 0;
  };
  /// What one camera draws with: its own, so that cameras are drawn side by side.
  struct Camera {
    std::unique_ptr<sim_render::Renderer> renderer;  ///< made when first drawn
    std::unique_ptr<LensCamera> lens_camera;         ///< instead, for a wide-angle camera
    size_t link_hint = 0;
    std::vector<uint8_t> rgb;  ///< frame before conversion to bgr8 / mono8
    std::vector<uint8_t> distorted;  ///< rgb through the distortion, when it has one
    DistortionMap distortion;        ///< made with the renderer, when it has one
    std::mt19937_64 rng;             ///< its image noise, seeded from (seed, robot, camera)
  };
  struct RobotScene {
    int spawn_generation = -1;  ///< tells a respawned robot of the same name apart
    std::vector<Visual> visuals;
    std::vector<Camera> cameras;       ///< by index in the spec
    std::vector<LinkPose> link_poses;  ///< as poseRobots() last read them
  };
  /// A frame that can be drawn, with all it needs read beforehand.
  struct Draw {
    CameraFrame* frame;
    const CameraSpec* camera;
    Camera* drawer;
    Eigen::Isometry3d T_world_camera;
  };

  explicit Impl(const Simulation& s) : sim(s) {
    const WorldSpec& world = sim.world();
    for (const StaticShape& s : world.shapes) {
      for (const sim_render::ShapeSpec& spec : shapesOf(s, s.mesh, s.rgba, s.texture, &sources)) {
        try {
          scene.add(spec, toIsometry(s.pose));
        } catch (const std::invalid_argument& e) {
          warnings.push_back("world shape of model '" + s.model + "' link '" + s.link +
                             "' not drawn: " + e.what());
        }
      }
    }
  }

  void addRobot(const std::string& name, const RobotSpec& spec, RobotScene* robot) {
    robot->spawn_generation = sim.spawnGeneration(name);
    robot->cameras.resize(spec.cameras.size());
    for (const VisualSpec& v : spec.visuals) {
      const Eigen::Isometry3d T_link_visual = toIsometry(v.pose_in_link);
      for (const sim_render::ShapeSpec& shape : shapesOf(v, v.mesh, v.rgba, v.texture, &sources)) {
        try {
          robot->visuals.push_back({v.link, 0, T_link_visual, scene.add(shape, T_link_visual)});
        } catch (const std::invalid_argument& e) {
          warnings.push_back("robot '" + name + "' link '" + v.link + "': visual not drawn: " +
                             e.what());
        }
      }
    }
  }

  void dropRobot(RobotScene* robot) {
    for (const Visual& v : robot->visuals) scene.remove(v.id);
    robot->visuals.clear();
  }

  /// Brings the scene's robots in line with the simulation's.
  void syncRobots() {
    const std::vector<std::string> names = sim.robotNames();
    const std::set<std::string> alive(names.begin(), names.end());
    for (auto it = robots.begin(); it != robots.end();) {
      if (alive.count(it->first) == 0) {
        dropRobot(&it->second);
        it = robots.erase(it);
      } else {
        ++it;
      }
    }
    for (const std::string& name : names) {
      auto it = robots.find(name);
      if (it != robots.end() && it->second.spawn_generation == sim.spawnGeneration(name)) {
        continue;
      }
      if (it != robots.end()) {
        dropRobot(&it->second);
        robots.erase(it);
      }
      addRobot(name, sim.robotSpec(name), &robots[name]);
    }
  }

  /// Moves every robot's visuals to their links' current poses, which it keeps.
  void poseRobots() {
    for (auto& [name, robot] : robots) {
      robot.link_poses = sim.linkPoses(name);
      for (Visual& v : robot.visuals) {
        const Pose3* link = findLink(robot.link_poses, v.link, &v.link_hint);
        if (link) scene.setPose(v.id, toIsometry(*link) * v.T_link_visual);
      }
    }
  }

  /// Makes `camera`'s renderer (or lens camera) the first time it is drawn.
  void prepareCamera(const std::string& robot, const CameraSpec& camera, Camera* drawer) const {
    if (drawer->renderer || drawer->lens_camera) return;
    validateCamera(camera);
    drawer->rng = sensorRng(sim.seed(), robot, camera.name);
    if (camera.distortion) {
      const CameraInfoData info = cameraInfo(camera, 0);
      const std::array<double, 2> c = distortionCentre(camera, info.K[2], info.K[5]);
      drawer->distortion = DistortionMap(*camera.distortion, camera.width, camera.height,
                                         info.K[0], c[0], c[1]);
    }
    if (camera.lens) {
      drawer->lens_camera = std::make_unique<LensCamera>(camera);
    } else {
      drawer->renderer = std::make_unique<sim_render::Renderer>(cameraModel(camera));
    }
  }

  /// World pose of `camera` on robot `robot`, whose links poseRobots() has just read.
  static Eigen::Isometry3d cameraPose(const std::string& robot, const RobotScene& scene_robot,
                                      const CameraSpec& camera, size_t* link_hint) {
    const Pose3* link = findLink(scene_robot.link_poses, camera.link, link_hint);
    if (!link) throw LoadError(cameraName(camera) + " of robot '" + robot + "': no such link");
    return toIsometry(*link) * toIsometry(camera.pose_in_link);
  }

  /// Everything `frame` needs to be drawn, its image's header set; after syncRobots() and
  /// poseRobots(). @throws what render() throws for the frame.
  Draw prepare(CameraFrame* frame) {
    const CameraSpec& camera = cameraToRender(sim.robotSpec(frame->robot), frame->robot,
                                               frame->index, frame->depth != nullptr);
    RobotScene& robot = robots.at(frame->robot);
    Camera& drawer = robot.cameras.at(frame->index);
    prepareCamera(frame->robot, camera, &drawer);
    const Eigen::Isometry3d T_world_camera =
        cameraPose(frame->robot, robot, camera, &drawer.link_hint);
    setImageHeader(camera, sim.timeS(), frame->image);
    return {frame, &camera, &drawer, T_world_camera};
  }

  /// Draws a prepared frame; reads the scene and writes only the frame's and its camera's
  /// buffers, so that frames of different cameras are drawn side by side.
  static void draw(const sim_render::Scene& scene, const Draw& d) {
    ImageData* image = d.frame->image;
    const bool rgb8 = image->encoding == "rgb8" && !d.camera->noise && !d.camera->distortion;
    std::vector<uint8_t>& rgb = rgb8 ? image->data : d.drawer->rgb;
    if (d.drawer->lens_camera) {
      d.drawer->lens_camera->render(scene, d.T_world_camera, rgb);
    } else {
      d.drawer->renderer->render(scene, d.T_world_camera, rgb);
    }
    if (d.frame->depth) readDepth(*d.drawer->renderer, *d.camera, image->time_s, d.frame->depth);
    if (rgb8) {
      image->step = 3 * d.camera->width;
    } else if (!d.camera->noise && !d.camera->distortion && image->encoding != "rgb16" &&
               image->encoding != "mono16") {
      encodeFromRgb(d.drawer->rgb, d.camera->width, image);
    } else {
      const std::vector<uint8_t>* frame = &d.drawer->rgb;
      if (!d.drawer->distortion.empty()) {
        d.drawer->distortion.apply(d.drawer->rgb, &d.drawer->distorted);
        frame = &d.drawer->distorted;
      }
      image->step = encodeFrame(*frame, d.camera->width, image->encoding,
                                d.camera->noise ? &*d.camera->noise : nullptr, &d.drawer->rng,
                                &image->data);
    }
  }

  const Simulation& sim;
  sim_render::Scene scene;
  std::map<std::string, RobotScene> robots;
  std::vector<std::string> warnings;
  ShapeSources sources{MeshTriangles(), TextureImages(&warnings), {}};
};

CameraRenderer::CameraRenderer(const Simulation& sim) : impl_(std::make_unique<Impl>(sim)) {}

CameraRenderer::~CameraRenderer() = default;

const std::vector<std::string>& CameraRenderer::warnings() const { return impl_->warnings; }

void CameraRenderer::render(const std::string& robot, size_t index, ImageData* image,
                            DepthImageData* depth) {
  std::vector<CameraFrame> frames(1);
  frames[0].robot = robot;
  frames[0].index = index;
  frames[0].image = image;
  frames[0].depth = depth;
  renderTogether(&frames);
  if (frames[0].error) std::rethrow_exception(frames[0].error);
}

void CameraRenderer::renderTogether(std::vector<CameraFrame>* frames) {
  requireDistinctCameras(*frames);
  impl_->syncRobots();
  impl_->poseRobots();
  lightScene(impl_->sim.world(), &impl_->scene.lighting());
  std::vector<Impl::Draw> draws;
  draws.reserve(frames->size());
  for (CameraFrame& frame : *frames) {
    frame.error = nullptr;
    try {
      draws.push_back(impl_->prepare(&frame));
    } catch (...) {
      frame.error = std::current_exception();
    }
  }
  const sim_render::Scene& scene = impl_->scene;
  impl_->sim.runInParallel(draws.size(), [&scene, &draws](size_t i) {
    try {
      Impl::draw(scene, draws[i]);
    } catch (...) {
      draws[i].frame->error = std::current_exception();
    }
  });
}

}  // namespace bullet_sim
