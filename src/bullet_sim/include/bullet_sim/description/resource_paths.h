#ifndef BULLET_SIM_RESOURCE_PATHS_H
#define BULLET_SIM_RESOURCE_PATHS_H

#include <future>
#include <map>
#include <string>
#include <vector>

namespace bullet_sim {

/// Where the URIs of worlds and robots are looked up: `model://NAME/...` in the model
/// folders (Gazebo's GAZEBO_MODEL_PATH, in its order), `package://PKG/...` in the ROS
/// packages found under the package path (ROS_PACKAGE_PATH, as rospack crawls it).
struct ResourcePaths {
  std::vector<std::string> model_paths;
  std::vector<std::string> package_paths;
  /// Model folders searched after `model_paths` that may still be being collected (the
  /// ROS packages' exports, which take a crawl of the package path): waited for only
  /// when a model is not in `model_paths`. Not valid: none.
  std::shared_future<std::vector<std::string>> later_model_paths{};

  /// GAZEBO_MODEL_PATH and ROS_PACKAGE_PATH of the process environment (':'-separated;
  /// empty entries are skipped), then the process's exported model paths, if set.
  static ResourcePaths fromEnvironment();
  /// Has every later fromEnvironment() search `paths` after GAZEBO_MODEL_PATH, as
  /// gazebo_ros adds the packages' `gazebo_model_path` exports to Gazebo's model path.
  static void setExportedModelPaths(std::shared_future<std::vector<std::string>> paths);
};

/// Resolves resource URIs to existing files, remembering where each package lives.
class UriResolver {
 public:
  explicit UriResolver(ResourcePaths paths);

  /// The path of the file `uri` names: `model://NAME/rest` (first model folder that holds
  /// NAME/rest), `package://PKG/rest`, `file:///abs`, an absolute path, or a path relative
  /// to `base_dir` (the folder of the file that names it; "" = the current folder).
  /// Returns "" when nothing is found; `searched` (if given) receives the folders looked at.
  std::string resolve(const std::string& uri, const std::string& base_dir,
                      std::vector<std::string>* searched = nullptr) const;

  /// The folder of a model named `name` (the first model path holding it), or "".
  std::string findModel(const std::string& name,
                        std::vector<std::string>* searched = nullptr) const;
  /// The folder of ROS package `name` under the package path, or "".
  std::string findPackage(const std::string& name) const;

  const ResourcePaths& paths() const { return paths_; }

 private:
  /// `root/relative` for the first model root (model_paths, then later_model_paths)
  /// where `is_wanted` holds for it, or "".
  template <class IsWanted>
  std::string findInModelRoots(const std::string& relative, IsWanted is_wanted,
                               std::vector<std::string>* searched) const;

  ResourcePaths paths_;
  mutable bool packages_crawled_ = false;
  mutable std::map<std::string, std::string> package_dirs_;  ///< name -> folder
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_RESOURCE_PATHS_H
