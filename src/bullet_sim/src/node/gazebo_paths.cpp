#include "gazebo_paths.h"

#include <bullet_sim/resource_paths.h>

#include <ros/package.h>

#include <algorithm>
#include <future>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace bullet_sim_node {
namespace {

/// The exported folders in rospack's order, each once (an export may list several,
/// ':'-separated, as GAZEBO_MODEL_PATH does).
std::vector<std::string> exportedModelPaths() {
  std::vector<std::pair<std::string, std::string>> exports;  // package, value
  ros::package::getPlugins("gazebo_ros", "gazebo_model_path", exports);
  std::vector<std::string> paths;
  for (const auto& entry : exports) {
    std::stringstream value(entry.second);
    std::string path;
    while (std::getline(value, path, ':')) {
      if (!path.empty() && std::find(paths.begin(), paths.end(), path) == paths.end())
        paths.push_back(path);
    }
  }
  return paths;
}

}  // namespace

void collectExportedModelPaths() {
  bullet_sim::ResourcePaths::setExportedModelPaths(
      std::async(std::launch::async, exportedModelPaths).share());
}

}  // namespace bullet_sim_node
