#include "gazebo_paths.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <future>
#include <memory>
#include <sstream>

#include <unistd.h>

namespace gazebo_ros_server {
namespace {

namespace fs = std::filesystem;

// package.xml export attribute -> environment variable it extends
const std::pair<const char*, const char*> kExports[] = {
    {"gazebo_model_path", "GAZEBO_MODEL_PATH"},
    {"gazebo_media_path", "GAZEBO_RESOURCE_PATH"},
    {"plugin_path", "GAZEBO_PLUGIN_PATH"},
};

/// A word for a POSIX shell command line.
std::string shellQuoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// What `command` writes to its standard output ("" if it cannot be run).
std::string outputOf(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>/dev/null").c_str(), "r"),
                                              pclose);
  std::string out;
  if (!pipe) return out;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
  return out;
}

void appendOnce(const std::string& path, std::vector<std::string>* paths) {
  if (!path.empty() && std::find(paths->begin(), paths->end(), path) == paths->end()) {
    paths->push_back(path);
  }
}

std::string strip(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

/// rospack's "package value" lines -> the values' folders in order, each once.
std::vector<std::string> pathsOf(const std::string& rospack_output) {
  std::vector<std::string> paths;
  std::stringstream lines(rospack_output);
  for (std::string line; std::getline(lines, line);) {
    line = strip(line);
    const size_t space = line.find(' ');
    std::stringstream value(space == std::string::npos ? "" : line.substr(space + 1));
    for (std::string path; std::getline(value, path, ':');) appendOnce(strip(path), &paths);
  }
  return paths;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

bool isExecutableFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::vector<std::string> splitPath(const std::string& value) {
  std::vector<std::string> parts;
  std::stringstream in(value);
  for (std::string part; std::getline(in, part, ':');) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

std::vector<std::string> exportedPaths(const std::string& attrib, const std::string& rospack) {
  return pathsOf(outputOf(shellQuoted(rospack) + " plugins --attrib=" + attrib + " gazebo_ros"));
}

Environment gazeboEnvironment(Environment env, const std::string& share_dir,
                              const std::string& rospack) {
  // Each rospack crawls the packages; they run side by side.
  std::vector<std::future<std::vector<std::string>>> running;
  for (const auto& e : kExports) {
    running.push_back(std::async(std::launch::async, exportedPaths, e.first, rospack));
  }
  const std::string share = share_dir.empty()
                                ? strip(outputOf(shellQuoted(rospack) + " find gazebo_ros"))
                                : share_dir;
  for (size_t i = 0; i < running.size(); ++i) {
    const std::string variable = kExports[i].second;
    std::vector<std::string> paths = splitPath(env[variable]);
    for (const std::string& path : running[i].get()) appendOnce(path, &paths);
    if (variable == "GAZEBO_RESOURCE_PATH") appendOnce(share, &paths);
    env[variable] = join(paths, ":");
  }
  return env;
}

std::string resolveWorld(const std::string& name, const Environment& env,
                         const std::string& cwd) {
  std::error_code ec;
  const fs::path candidate = fs::path(name).is_absolute() ? fs::path(name) : fs::path(cwd) / name;
  if (fs::is_regular_file(candidate, ec)) return fs::absolute(candidate).lexically_normal();
  const auto resource = env.find("GAZEBO_RESOURCE_PATH");
  const std::vector<std::string> searched =
      splitPath(resource == env.end() ? "" : resource->second);
  for (const std::string& folder : searched) {
    const fs::path path = fs::path(folder) / name;
    if (fs::is_regular_file(path, ec)) return fs::absolute(path).lexically_normal();
  }
  throw WorldNotFound("world \"" + name +
                      "\" not found: not a file, and not in GAZEBO_RESOURCE_PATH (" +
                      (searched.empty() ? "empty" : join(searched, ", ")) + ")");
}

std::pair<Environment, std::string> serverEnvironment(const std::string& world,
                                                      const Environment& env,
                                                      const std::string& cwd,
                                                      const std::string& rospack) {
  try {
    return {env, resolveWorld(world, {}, cwd)};  // a file: no folders to search
  } catch (const WorldNotFound&) {
    Environment extended = gazeboEnvironment(env, "", rospack);
    const std::string path = resolveWorld(world, extended, cwd);
    return {extended, path};
  }
}

std::string workspaceExecutable(const std::string& project, const std::string& name,
                                const Environment& env) {
  const auto prefixes = env.find("CMAKE_PREFIX_PATH");
  if (prefixes == env.end()) return "";
  std::error_code ec;
  for (const std::string& prefix : splitPath(prefixes->second)) {
    if (!fs::is_regular_file(fs::path(prefix) / ".catkin", ec)) continue;
    const fs::path path = fs::path(prefix) / "lib" / project / name;
    if (isExecutableFile(path)) return path.string();
  }
  return "";
}

}  // namespace gazebo_ros_server
