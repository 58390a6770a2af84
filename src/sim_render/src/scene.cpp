#include "sim_render/scene.h"

#include <stdexcept>
#include <string>

namespace sim_render {

Scene::Scene(const TessellationOptions& options) : options_(options) {}

ShapeId Scene::add(const ShapeSpec& spec, const Eigen::Isometry3d& T_world_shape) {
  SceneShape shape;
  shape.mesh = tessellate(spec, options_);
  shape.id = next_id_++;
  shape.spec = spec;
  shape.T_world_shape = T_world_shape;
  index_[shape.id] = shapes_.size();
  shapes_.push_back(std::move(shape));
  return shapes_.back().id;
}

void Scene::setPose(ShapeId id, const Eigen::Isometry3d& T_world_shape) {
  mutableShape(id).T_world_shape = T_world_shape;
}

void Scene::setColor(ShapeId id, const Eigen::Vector4f& rgba) { mutableShape(id).spec.rgba = rgba; }

bool Scene::remove(ShapeId id) {
  const auto it = index_.find(id);
  if (it == index_.end()) return false;
  const std::size_t slot = it->second;
  index_.erase(it);
  if (slot + 1 != shapes_.size()) {
    shapes_[slot] = std::move(shapes_.back());
    index_[shapes_[slot].id] = slot;
  }
  shapes_.pop_back();
  return true;
}

void Scene::clear() {
  shapes_.clear();
  index_.clear();
}

std::size_t Scene::slotOf(ShapeId id) const {
  const auto it = index_.find(id);
  if (it == index_.end()) throw std::out_of_range("sim_render::Scene: unknown shape id " + std::to_string(id));
  return it->second;
}

const SceneShape& Scene::shape(ShapeId id) const { return shapes_[slotOf(id)]; }

SceneShape& Scene::mutableShape(ShapeId id) { return shapes_[slotOf(id)]; }

}  // namespace sim_render
