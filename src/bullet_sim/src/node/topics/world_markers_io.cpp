#include "topics/world_markers_io.h"

#include "topics/conversions.h"

#include <cstdlib>
#include <set>
#include <utility>

#include <ros/console.h>
#include <visualization_msgs/MarkerArray.h>

#include "bullet_sim/render/textured_mesh.h"

namespace bullet_sim_node {
namespace {

// A moving model is redrawn this often at most: smooth enough to follow in RViz, and the
// check costs nothing noticeable when the simulation runs many times real time.
constexpr std::chrono::milliseconds kCheckPeriod{200};
// Spawned robots drive: followed 20 times a second, a few markers each.
constexpr std::chrono::milliseconds kModelCheckPeriod{50};
// Motions smaller than these do not resend the array.
constexpr double kPositionToleranceM = 0.001;
constexpr double kAngleToleranceRad = 0.002;

/// Where the textured meshes of material-script textures are written for RViz:
/// $ROS_HOME/bullet_sim/marker_meshes (ROS_HOME defaults to ~/.ros, as for ROS's logs).
std::string markerMeshFolder() {
  const char* ros_home = std::getenv("ROS_HOME");
  const char* home = std::getenv("HOME");
  const std::string base = ros_home ? ros_home : std::string(home ? home : "/tmp") + "/.ros";
  return base + "/bullet_sim/marker_meshes";
}

/// A textured box or plane as a mesh RViz draws with its texture; when the mesh cannot be
/// written, the plain shape in its colour (and one warning).
void setTexturedShape(const bullet_sim::MarkerShape& shape, visualization_msgs::Marker* m) {
  std::string reason;
  const std::string path = bullet_sim::writeTexturedMesh(*shape.textured_geometry, shape.texture,
                                                         markerMeshFolder(), &reason);
  if (!path.empty()) {
    m->type = visualization_msgs::Marker::MESH_RESOURCE;
    m->mesh_resource = "file://" + path;
    m->mesh_use_embedded_materials = true;
    return;
  }
  ROS_WARN_STREAM_ONCE("world marker of " << shape.ns << " drawn without its texture "
                                          << shape.texture.path << ": " << reason);
  const sim_render::Geometry& g = *shape.textured_geometry;
  m->type = visualization_msgs::Marker::CUBE;
  m->scale.x = g.size.x();
  m->scale.y = g.size.y();
  m->scale.z = g.kind == sim_render::Geometry::Box ? g.size.z() : 0.002;
  m->color.r = shape.rgba[0];
  m->color.g = shape.rgba[1];
  m->color.b = shape.rgba[2];
  m->color.a = shape.rgba[3];
}

visualization_msgs::Marker toMarkerMsg(const bullet_sim::MarkerShape& shape) {
  visualization_msgs::Marker m;
  m.header.frame_id = "world";
  // Stamp 0: RViz uses the newest transform, so a static marker never waits for tf history.
  m.header.stamp = ros::Time(0);
  m.ns = shape.ns;
  m.id = shape.id;
  switch (shape.type) {
    case bullet_sim::MarkerShape::Cube: m.type = visualization_msgs::Marker::CUBE; break;
    case bullet_sim::MarkerShape::Cylinder: m.type = visualization_msgs::Marker::CYLINDER; break;
    case bullet_sim::MarkerShape::Sphere: m.type = visualization_msgs::Marker::SPHERE; break;
    case bullet_sim::MarkerShape::Mesh:
      m.type = visualization_msgs::Marker::MESH_RESOURCE;
      m.mesh_resource = shape.mesh_resource;
      break;
  }
  m.action = visualization_msgs::Marker::ADD;
  m.pose = toMsg(shape.pose);
  m.scale.x = shape.scale_m.x();
  m.scale.y = shape.scale_m.y();
  m.scale.z = shape.scale_m.z();
  m.color.r = shape.rgba[0];
  m.color.g = shape.rgba[1];
  m.color.b = shape.rgba[2];
  m.color.a = shape.rgba[3];
  m.frame_locked = false;
  if (shape.embedded_materials) {
    // The file's own textures, untinted: RViz blends in any colour that is not 0 0 0 0.
    m.mesh_use_embedded_materials = true;
    m.color = std_msgs::ColorRGBA();
  }
  if (shape.textured_geometry) setTexturedShape(shape, &m);
  return m;
}

}  // namespace

WorldMarkersIo::Topic::Topic(bullet_sim::WorldMarkerSet marker_set,
                             std::chrono::milliseconds check_period)
    : set(std::move(marker_set)),
      period(check_period),
      last_check(std::chrono::steady_clock::now()) {}

void WorldMarkersIo::Topic::advertise(ros::NodeHandle& nh, const std::string& name) {
  pub = nh.advertise<visualization_msgs::MarkerArray>(name, 1, true);
}

void WorldMarkersIo::Topic::update(const bullet_sim::Simulation& sim,
                                   std::chrono::steady_clock::time_point now) {
  if (now - last_check < period) return;
  last_check = now;
  if (pub.getNumSubscribers() == 0) return;
  if (const auto all = set.update(sim)) publish(*all);
}

void WorldMarkersIo::Topic::publish(const std::vector<bullet_sim::MarkerShape>& markers) const {
  visualization_msgs::MarkerArray array;
  // The array is always complete: clear what a listener drew before (a deleted model's
  // markers with it), then draw everything again.
  visualization_msgs::Marker clear;
  clear.header.frame_id = "world";
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);
  for (const auto& shape : markers) array.markers.push_back(toMarkerMsg(shape));
  pub.publish(array);
}

WorldMarkersIo::WorldMarkersIo(const bullet_sim::Simulation& sim, const ros::NodeHandle& nh)
    : sim_(sim),
      world_(bullet_sim::WorldMarkerSet(sim.world(), kPositionToleranceM, kAngleToleranceRad),
             kCheckPeriod),
      models_(bullet_sim::WorldMarkerSet(bullet_sim::WorldSpec(), kPositionToleranceM,
                                         kAngleToleranceRad),
              kModelCheckPeriod) {
  ros::NodeHandle handle(nh);
  world_.advertise(handle, "world_markers");
  models_.advertise(handle, "model_markers");
  std::set<std::string> world_models;
  for (const bullet_sim::WorldModel& model : sim.world().models) world_models.insert(model.name);
  models_.set.trackEveryModelBut(world_models);
  // Latched at once, listened to or not.
  if (const auto all = world_.set.update(sim_)) world_.publish(*all);
  if (const auto all = models_.set.update(sim_)) models_.publish(*all);
}

void WorldMarkersIo::update() {
  const auto now = std::chrono::steady_clock::now();
  models_.update(sim_, now);
  world_.update(sim_, now);
}

}  // namespace bullet_sim_node
