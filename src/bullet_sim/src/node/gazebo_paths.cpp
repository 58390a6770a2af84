#include "gazebo_paths.h"

#include <bullet_sim/description/resource_paths.h>

#include <algorithm>
#include <cstdio>
#include <future>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace bullet_sim_node {
namespace {

/// What `command` writes to its standard output ("" if it cannot be run).
std::string outputOf(const char* command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command, "r"), pclose);
  std::string out;
  if (!pipe) return out;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
  return out;
}

/// The exported folders in rospack's order, each once (an export may list several,
/// ':'-separated, as GAZEBO_MODEL_PATH does). rospack runs as a process of its own: its
/// crawl of the package path parses every package.xml, and would leave a few megabytes of
/// the simulator's heap in pieces that cannot go back to the system.
std::vector<std::string> exportedModelPaths() {
  std::stringstream lines(
      outputOf("rospack plugins --attrib=gazebo_model_path gazebo_ros 2>/dev/null"));
  std::vector<std::string> paths;
  for (std::string line; std::getline(lines, line);) {
    // "package value"
    std::stringstream value(line.substr(std::min(line.size(), line.find(' ') + 1)));
    for (std::string path; std::getline(value, path, ':');) {
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
