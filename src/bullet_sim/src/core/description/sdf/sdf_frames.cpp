#include "description/sdf/sdf_frames.h"

namespace bullet_sim {

void FrameScope::add(const std::string& name, const RawPose& pose, const std::string& default_to,
                     const tinyxml2::XMLElement* e, const SdfValues& values) {
  if (name == own_frame_ || frames_.count(name)) {
    // Names need be unique among a model's frames from SDF 1.7 on; in older files a pose
    // can only name a link, and the first of that name is kept.
    if (values.version().before(1, 7)) return;
    values.fail(e, "a frame named '" + name + "' already exists in " + where_);
  }
  const std::string relative_to = pose.relative_to.empty() ? default_to : pose.relative_to;
  frames_[name] = Entry{pose, relative_to, e, &values};
}

void FrameScope::addNested(const std::string& name, std::unique_ptr<FrameScope> nested) {
  nested_[name] = std::move(nested);
}

bool FrameScope::has(const std::string& name) const {
  if (name == own_frame_ || frames_.count(name)) return true;
  const auto sep = name.find("::");
  if (sep == std::string::npos) return false;
  const auto nested = nested_.find(name.substr(0, sep));
  return nested != nested_.end() && nested->second->has(name.substr(sep + 2));
}

Eigen::Isometry3d FrameScope::resolve(const std::string& name, const tinyxml2::XMLElement* e,
                                      const SdfValues& values) const {
  std::set<std::string> visiting;
  return resolve(name, e, values, &visiting);
}

Eigen::Isometry3d FrameScope::resolve(const std::string& name, const tinyxml2::XMLElement* e,
                                      const SdfValues& values,
                                      std::set<std::string>* visiting) const {
  if (name == own_frame_ || name.empty()) return Eigen::Isometry3d::Identity();
  const auto done = resolved_.find(name);
  if (done != resolved_.end()) return done->second;
  const auto entry = frames_.find(name);
  if (entry == frames_.end()) {
    const auto sep = name.find("::");
    const auto nested = sep == std::string::npos ? nested_.end() : nested_.find(name.substr(0, sep));
    if (nested == nested_.end()) {
      values.fail(e, "pose relative_to/frame '" + name + "' names no frame of " + where_);
    }
    return resolve(name.substr(0, sep), e, values, visiting) *
           nested->second->resolve(name.substr(sep + 2), e, values);
  }
  if (!visiting->insert(name).second) {
    std::string cycle;
    for (const std::string& f : *visiting) cycle += (cycle.empty() ? "" : ", ") + f;
    entry->second.values->fail(entry->second.element,
                               "the poses of frames " + cycle + " are relative to each other "
                               "in a cycle (in " + where_ + ")");
  }
  const Entry& f = entry->second;
  const Eigen::Isometry3d T = resolve(f.relative_to, f.element, *f.values, visiting) * f.pose.T;
  visiting->erase(name);
  resolved_[name] = T;
  return T;
}

Eigen::Isometry3d FrameScope::resolvePose(const RawPose& pose, const std::string& default_to,
                                          const tinyxml2::XMLElement* e,
                                          const SdfValues& values) const {
  const std::string relative_to = pose.relative_to.empty() ? default_to : pose.relative_to;
  return resolve(relative_to, e, values) * pose.T;
}

}  // namespace bullet_sim
