// Gazebo's search paths as gazebo_ros users set them.
//
// Gazebo finds `model://` folders in GAZEBO_MODEL_PATH, world names such as
// `worlds/empty.world` in GAZEBO_RESOURCE_PATH, and gazebo_ros adds the paths that packages
// export in their package.xml (`<export><gazebo_ros gazebo_model_path="..."/></export>`),
// collected with `rospack plugins --attrib=ATTRIB gazebo_ros` (a package must depend on
// gazebo_ros for rospack to list it).
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gazebo_ros_server {

using Environment = std::map<std::string, std::string>;

/// A world name found neither as a file nor in GAZEBO_RESOURCE_PATH.
class WorldNotFound : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The non-empty entries of a ':'-separated path list.
std::vector<std::string> splitPath(const std::string& value);

/// The values of `<gazebo_ros ATTRIB="..."/>` of every package that depends on
/// gazebo_ros, in rospack's order, each once (`${prefix}` already expanded by rospack).
std::vector<std::string> exportedPaths(const std::string& attrib,
                                       const std::string& rospack = "rospack");

/// `env` with its Gazebo paths extended by the package exports (model, media and plugin
/// paths; the rospack queries run side by side) and this package's own folder for
/// `worlds/...` names (`share_dir`; "" asks `rospack find gazebo_ros`). Entries already
/// set come first, as in Gazebo.
Environment gazeboEnvironment(Environment env, const std::string& share_dir = "",
                              const std::string& rospack = "rospack");

/// The file a world argument names: an existing path (absolute or relative to `cwd`),
/// else a name looked up in every GAZEBO_RESOURCE_PATH folder of `env`, as gzserver does.
/// Throws WorldNotFound naming the folders searched.
std::string resolveWorld(const std::string& name, const Environment& env,
                         const std::string& cwd);

/// The environment gzserver starts the simulator in, and the world file it loads. A world
/// given as a file needs no lookup and the environment stays as it is (the simulator
/// collects the packages' model folders itself while it loads the world); a world given
/// by name is looked up with the exports added (a crawl of the package path each).
std::pair<Environment, std::string> serverEnvironment(const std::string& world,
                                                      const Environment& env,
                                                      const std::string& cwd,
                                                      const std::string& rospack = "rospack");

/// `lib/PROJECT/NAME` in the first catkin workspace (a prefix with a `.catkin` file) of
/// CMAKE_PREFIX_PATH that has it as an executable, or "".
std::string workspaceExecutable(const std::string& project, const std::string& name,
                                const Environment& env);

}  // namespace gazebo_ros_server
