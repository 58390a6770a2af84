#ifndef BULLET_SIM_TEST_DIFFERENTIAL_CORPUS_H
#define BULLET_SIM_TEST_DIFFERENTIAL_CORPUS_H

#include <string>
#include <vector>

namespace bullet_sim_test {

/// One SDF file to read with both readers, and the model folders its <include>s and
/// model:// URIs are looked up in (as GAZEBO_MODEL_PATH would list them).
struct CorpusFile {
  std::string path;
  std::vector<std::string> model_paths;
};

/// A workspace file left out of the comparison, and why.
struct Exclusion {
  std::string relative_path;  ///< to the workspace root
  std::string reason;
};

/// Workspace files whose purpose is to be unreadable (fixtures of the readers' own error
/// messages): there is nothing to compare in them.
const std::vector<Exclusion>& workspaceExclusions();

/// Every .world and .sdf file under `workspace_root`/src but the exclusions, sorted; their
/// model folders are the workspace's folders of models (each a folder holding model
/// folders with a model.config), the built-in sun and ground_plane excepted.
std::vector<CorpusFile> workspaceCorpus(const std::string& workspace_root);

/// A file that libsdformat 12 refuses and Gazebo classic reads, for a reason its errors do
/// not carry (they name the element, not the rule): matched by the end of its path.
struct KnownRefusal {
  std::string path_suffix;
  std::string reason;
};

/// Why libsdformat 12 is known to refuse `path` though Gazebo classic reads it, or "".
std::string knownRefusalOf(const std::string& path);

/// A clone of an upstream repository found on this machine.
struct UpstreamClone {
  std::string kind;  ///< "training turtlebot3_simulations", ... (see upstreamClones)
  std::string root;  ///< the folder whose files are read
  std::vector<std::string> model_paths;
};

/// The clones under the workspaces of MOBILITY_UPSTREAM_WS (':'-separated; each a catkin
/// workspace or a source folder): a `turtlebot3_gazebo` with a `worlds` folder is the
/// training's clone of turtlebot3_simulations when it has the training's
/// launch/roundTrack_simulation.launch, ROBOTIS's otherwise; a `gazebo_plugins` with a
/// `test` folder is gazebo_ros_pkgs. Folders inside `workspace_root` (this workspace's
/// own turtlebot3_gazebo) are not clones.
std::vector<UpstreamClone> upstreamClones(const std::string& workspace_root);

/// The .world and .sdf files under the clone's root, sorted.
std::vector<CorpusFile> cloneCorpus(const UpstreamClone& clone);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_DIFFERENTIAL_CORPUS_H
