// gazebo_ros's gzserver: starts bullet_sim_node (in place of Gazebo's server) with the
// world that gzserver's command line names. A world given by name (worlds/empty.world) is
// looked up in GAZEBO_RESOURCE_PATH with the packages' package.xml exports added, as
// gazebo_ros does; the model folders they export are collected by the simulator itself
// while it loads the world (as gazebo_ros's paths plugin does inside gzserver).
#include "gazebo_paths.h"
#include "server_args.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

extern char** environ;

namespace {

using namespace gazebo_ros_server;

Environment currentEnvironment() {
  Environment env;
  for (char** entry = environ; *entry; ++entry) {
    const std::string text = *entry;
    const size_t eq = text.find('=');
    if (eq != std::string::npos) env[text.substr(0, eq)] = text.substr(eq + 1);
  }
  return env;
}

std::string currentDirectory() {
  std::vector<char> buffer(4096);
  return getcwd(buffer.data(), buffer.size()) ? buffer.data() : ".";
}

/// `name` found in PATH, as shutil.which finds it, or "".
std::string which(const std::string& name, const Environment& env) {
  const auto path = env.find("PATH");
  for (const std::string& folder : splitPath(path == env.end() ? "" : path->second)) {
    const std::string candidate = folder + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

/// Replaces this process by `command` in `env`; returns only on failure.
int exec(const std::vector<std::string>& command, const Environment& env) {
  std::vector<std::string> entries;
  for (const auto& e : env) entries.push_back(e.first + "=" + e.second);
  std::vector<char*> argv, envp;
  for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
  for (const std::string& entry : entries) envp.push_back(const_cast<char*>(entry.c_str()));
  argv.push_back(nullptr);
  envp.push_back(nullptr);
  execve(argv[0], argv.data(), envp.data());
  std::cerr << "gzserver: cannot start " << command[0] << ": " << std::strerror(errno)
            << std::endl;
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  ServerArgs args;
  Environment env;
  std::string world;
  try {
    args = parseServerArgs(std::vector<std::string>(argv + 1, argv + argc));
    std::tie(env, world) = serverEnvironment(args.world.empty() ? "worlds/empty.world" : args.world,
                                             currentEnvironment(), currentDirectory());
  } catch (const std::runtime_error& error) {  // ServerArgsError, WorldNotFound
    std::cerr << "gzserver: " << error.what() << std::endl;
    return 1;
  }
  for (const std::string& option : args.ignored) {
    std::cout << "gzserver: option " << option << " has no effect here (bullet_sim)\n";
  }
  if (args.physics != "ode") {
    std::cout << "gzserver: physics engine \"" << args.physics
              << "\" requested; bullet_sim simulates with Bullet\n";
  }
  std::cout << std::flush;
  const std::string node = workspaceExecutable("bullet_sim", "bullet_sim_node", env);
  if (node.empty()) {
    std::cerr << "gzserver: bullet_sim_node is not built (run make build)" << std::endl;
    return 1;
  }
  std::vector<std::string> command = {node};
  for (const std::string& word : nodeArguments(args, world)) command.push_back(word);
  const char* debug = std::getenv("GAZEBO_ROS_DEBUG");
  const std::string gdb = which("gdb", env);
  if (debug && std::string(debug) == "1" && !gdb.empty()) {
    command.insert(command.begin(), {gdb, "-ex", "run", "--args"});
  }
  return exec(command, env);
}
