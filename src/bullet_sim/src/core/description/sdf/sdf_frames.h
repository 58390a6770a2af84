#ifndef BULLET_SIM_CORE_SDF_FRAMES_H
#define BULLET_SIM_CORE_SDF_FRAMES_H

#include <map>
#include <memory>
#include <set>
#include <string>

#include <Eigen/Geometry>
#include <tinyxml2.h>

#include "description/sdf/sdf_values.h"

namespace bullet_sim {

/// The named frames of one model (or of the world) and the poses that place them, as SDF
/// 1.7 defines them: each pose is relative to another frame of the same scope (its
/// `relative_to`, else a default: the model frame for links and nested models, the child
/// link for joints, the `attached_to` frame for <frame>s), and every frame resolves into
/// the scope's own frame ("__model__" of a model, "world" of a world). A nested model's
/// frames are reached as "nested::name". Older files resolve the same way: their poses
/// have no relative_to but the 1.5/1.6 `frame` attribute (SdfValues::pose).
class FrameScope {
 public:
  /// `own_frame`: "__model__" or "world"; `where` names the scope in messages.
  FrameScope(std::string own_frame, std::string where)
      : own_frame_(std::move(own_frame)), where_(std::move(where)) {}

  /// Frame `name`, placed by `pose` (relative to `default_to` when pose.relative_to is "").
  /// `e` is the element that defines it (for messages).
  /// @throws LoadError naming `e` when a frame of that name exists (SDF 1.7 and later; an
  /// older file keeps the first).
  void add(const std::string& name, const RawPose& pose, const std::string& default_to,
           const tinyxml2::XMLElement* e, const SdfValues& values);
  /// The frames of nested model `name` (already added with add()), posed in its frame.
  void addNested(const std::string& name, std::unique_ptr<FrameScope> nested);

  bool has(const std::string& name) const;
  /// The pose of frame `name` in the scope's own frame.
  /// @throws LoadError naming the element that asks (`e`) for an unknown frame, and the
  /// frames of a cycle.
  Eigen::Isometry3d resolve(const std::string& name, const tinyxml2::XMLElement* e,
                            const SdfValues& values) const;
  /// The pose of an element that is no frame of the scope (a visual, a light), placed by
  /// `pose` relative to `default_to` when it names none.
  Eigen::Isometry3d resolvePose(const RawPose& pose, const std::string& default_to,
                                const tinyxml2::XMLElement* e, const SdfValues& values) const;

 private:
  struct Entry {
    RawPose pose;
    std::string relative_to;
    const tinyxml2::XMLElement* element;
    const SdfValues* values;
  };
  Eigen::Isometry3d resolve(const std::string& name, const tinyxml2::XMLElement* e,
                            const SdfValues& values, std::set<std::string>* visiting) const;

  std::string own_frame_, where_;
  std::map<std::string, Entry> frames_;
  std::map<std::string, std::unique_ptr<FrameScope>> nested_;
  mutable std::map<std::string, Eigen::Isometry3d> resolved_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_FRAMES_H
