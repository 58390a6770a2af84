#include "differential_corpus.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace bullet_sim_test {

namespace fs = std::filesystem;

namespace {

bool isSdfFile(const fs::path& p) { return p.extension() == ".world" || p.extension() == ".sdf"; }

/// Folders a walk does not enter: hidden ones and catkin's build products.
bool isSkipped(const fs::path& dir) {
  const std::string name = dir.filename().string();
  return name.empty() || name[0] == '.' || name == "build" || name == "devel" ||
         name == "install";
}

/// Every file (when `files`) or folder under `root` for which `wanted` holds, at most
/// `depth` levels down, sorted.
template <class Wanted>
std::vector<std::string> walk(const fs::path& root, int depth, bool files, Wanted wanted) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return out;
  for (fs::recursive_directory_iterator it(root, ec), end; it != end; it.increment(ec)) {
    if (ec) break;
    const bool is_dir = it->is_directory(ec);
    if (is_dir && (isSkipped(it->path()) || it.depth() >= depth)) {
      it.disable_recursion_pending();
      if (isSkipped(it->path())) continue;
    }
    if (is_dir != files && wanted(it->path())) out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool holdsModels(const fs::path& dir) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; it != end; it.increment(ec)) {
    if (fs::is_regular_file(it->path() / "model.config", ec)) return true;
  }
  return false;
}

bool isInside(const fs::path& path, const fs::path& root) {
  std::error_code ec;
  const std::string p = fs::weakly_canonical(path, ec).string() + "/";
  const std::string r = fs::weakly_canonical(root, ec).string() + "/";
  return p.compare(0, r.size(), r) == 0;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, separator);) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

}  // namespace

const std::vector<Exclusion>& workspaceExclusions() {
  static const std::vector<Exclusion> exclusions = {
      {"src/bullet_sim/test/fixtures/world_malformed.world",
       "not well-formed XML: the fixture of the malformed-world message"},
      {"src/bullet_sim/test/ros/fixtures/malformed.world",
       "not well-formed XML: the node's FATAL message on a malformed world"},
      {"src/bullet_sim/test/fixtures/world_bad_sdf_version.world",
       "<sdf version=\"1.;\">: the fixture of the bad-version message"},
      {"src/bullet_sim/test/fixtures/world_missing_include.world",
       "includes model://no_such_model: the fixture of the missing-include message"},
      {"src/bullet_sim/test/fixtures/world_state_bad_pose.world",
       "a <state> pose that is not six numbers: the fixture of that message"},
      {"src/turtlebot3_gazebo/test/map_worlds/bad_size.world",
       "<size>0.015 wide 0.5</size>: the fixture of the map maker's bad-size message"},
  };
  return exclusions;
}

std::string knownRefusalOf(const std::string& path) {
  static const std::vector<KnownRefusal> refusals = {
      {"gazebo_plugins/test/test_worlds/bumper_test.world",
       "<mu>-1</mu>: libsdformat 12 holds <mu> to the minimum 0 of its surface.sdf (checked "
       "since sdformat 11); sdformat 9, Gazebo classic's, reads -1"},
  };
  for (const KnownRefusal& r : refusals) {
    if (path.size() >= r.path_suffix.size() &&
        path.compare(path.size() - r.path_suffix.size(), r.path_suffix.size(), r.path_suffix) ==
            0) {
      return r.reason;
    }
  }
  return "";
}

std::vector<CorpusFile> workspaceCorpus(const std::string& workspace_root) {
  const fs::path src = fs::path(workspace_root) / "src";
  const fs::path builtin = src / "bullet_sim" / "models";
  std::vector<std::string> model_paths;
  for (const std::string& dir : walk(src, 6, false, [&](const fs::path& p) {
         return p.filename() == "models" && p != builtin && holdsModels(p);
       })) {
    model_paths.push_back(dir);
  }
  std::vector<CorpusFile> out;
  for (const std::string& file : walk(src, 10, true, isSdfFile)) {
    const std::string relative = fs::path(file).lexically_relative(workspace_root).string();
    // The world fuzz target's seeds are copies of these files and of the generated fixtures.
    if (relative.rfind("src/bullet_sim/fuzz/", 0) == 0) continue;
    const auto& ex = workspaceExclusions();
    if (std::any_of(ex.begin(), ex.end(),
                    [&](const Exclusion& e) { return e.relative_path == relative; })) {
      continue;
    }
    out.push_back({file, model_paths});
  }
  return out;
}

std::vector<UpstreamClone> upstreamClones(const std::string& workspace_root) {
  std::vector<UpstreamClone> out;
  const char* env = std::getenv("MOBILITY_UPSTREAM_WS");
  for (const std::string& ws : split(env ? env : "", ':')) {
    const fs::path src = fs::is_directory(fs::path(ws) / "src") ? fs::path(ws) / "src" : fs::path(ws);
    const auto named = [](const char* name) {
      return [name](const fs::path& p) { return p.filename() == name; };
    };
    for (const std::string& dir : walk(src, 4, false, named("turtlebot3_gazebo"))) {
      if (isInside(dir, workspace_root) || !fs::is_directory(fs::path(dir) / "worlds")) continue;
      const bool training = fs::exists(fs::path(dir) / "launch/roundTrack_simulation.launch");
      out.push_back({training ? "training turtlebot3_simulations"
                              : "ROBOTIS turtlebot3_simulations",
                     dir, {(fs::path(dir) / "models").string()}});
    }
    for (const std::string& dir : walk(src, 4, false, named("gazebo_plugins"))) {
      if (isInside(dir, workspace_root) || !fs::is_directory(fs::path(dir) / "test")) continue;
      out.push_back({"gazebo_ros_pkgs", fs::path(dir).parent_path().string(), {}});
    }
  }
  return out;
}

std::vector<CorpusFile> cloneCorpus(const UpstreamClone& clone) {
  std::vector<CorpusFile> out;
  for (const std::string& file : walk(clone.root, 10, true, isSdfFile)) {
    out.push_back({file, clone.model_paths});
  }
  return out;
}

}  // namespace bullet_sim_test
