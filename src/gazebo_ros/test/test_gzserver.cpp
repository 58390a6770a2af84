// gzserver's command line, and model and world paths collected as gazebo_ros collects them.
#include "../src/gzserver/gazebo_paths.h"
#include "../src/gzserver/server_args.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

using namespace gazebo_ros_server;
namespace fs = std::filesystem;

namespace {

void touch(const fs::path& path, bool executable = false) {
  fs::create_directories(path.parent_path());
  std::ofstream(path.string()).close();
  if (executable) chmod(path.c_str(), 0755);
}

class Paths : public testing::Test {
 protected:
  void SetUp() override {
    char name[] = "/tmp/gzserver_paths_XXXXXX";
    tmp_ = mkdtemp(name);
    // A stand-in for rospack that answers `rospack plugins --attrib=A gazebo_ros` and
    // `rospack find gazebo_ros`, and logs its calls.
    rospack_ = (tmp_ / "rospack").string();
    log_ = (tmp_ / "rospack.log").string();
    std::ofstream script(rospack_);
    script << "#!/bin/sh\necho \"$@\" >> " << log_ << "\ncase \"$2\" in\n"
           << "  --attrib=gazebo_model_path) echo \"pkg_a /a/models:/a/more\";"
              " echo \"pkg_b /b/models\";;\n"
           << "  --attrib=gazebo_media_path) echo \"pkg_a /a/media\";;\n"
           << "  gazebo_ros) echo \"/share/found\";;\nesac\n";
    script.close();
    chmod(rospack_.c_str(), 0755);
  }
  void TearDown() override { fs::remove_all(tmp_); }

  std::vector<std::string> rospackCalls() const {
    std::ifstream in(log_);
    std::vector<std::string> calls;
    for (std::string line; std::getline(in, line);) calls.push_back(line);
    return calls;
  }

  fs::path tmp_;
  std::string rospack_, log_;
};

}  // namespace

TEST_F(Paths, ExportsFollowWhatTheEnvironmentAlreadyHolds) {
  const Environment env =
      gazeboEnvironment({{"GAZEBO_MODEL_PATH", "/mine:/a/more"}}, "/share/gz", rospack_);
  EXPECT_EQ(env.at("GAZEBO_MODEL_PATH"), "/mine:/a/more:/a/models:/b/models");
  EXPECT_EQ(env.at("GAZEBO_RESOURCE_PATH"), "/a/media:/share/gz");
  EXPECT_EQ(env.at("GAZEBO_PLUGIN_PATH"), "");
}

TEST_F(Paths, ThePackageFolderComesFromRospackFindWhenNotGiven) {
  EXPECT_EQ(gazeboEnvironment({}, "", rospack_).at("GAZEBO_RESOURCE_PATH"),
            "/a/media:/share/found");
}

TEST_F(Paths, TheNodeIsFoundInTheFirstCatkinWorkspaceThatHasIt) {
  auto workspace = [&](const std::string& name, bool with_node) {
    const fs::path prefix = tmp_ / name;
    touch(prefix / ".catkin");
    fs::create_directories(prefix / "lib" / "bullet_sim");
    if (with_node) touch(prefix / "lib" / "bullet_sim" / "bullet_sim_node", true);
    return prefix.string();
  };
  const fs::path plain = tmp_ / "plain";  // no .catkin: not a workspace
  touch(plain / "lib" / "bullet_sim" / "bullet_sim_node", true);
  const fs::path not_executable = tmp_ / "plainfile";
  touch(not_executable / ".catkin");
  touch(not_executable / "lib" / "bullet_sim" / "bullet_sim_node");
  const Environment env = {
      {"CMAKE_PREFIX_PATH", plain.string() + ":" + not_executable.string() + ":" +
                                workspace("empty", false) + ":" + workspace("devel", true) +
                                ":" + workspace("opt", true)}};
  EXPECT_EQ(workspaceExecutable("bullet_sim", "bullet_sim_node", env),
            (tmp_ / "devel" / "lib" / "bullet_sim" / "bullet_sim_node").string());
  EXPECT_EQ(workspaceExecutable("bullet_sim", "nothing", env), "");
  EXPECT_EQ(workspaceExecutable("bullet_sim", "bullet_sim_node", {}), "");
}

TEST_F(Paths, RealRospackListsAbsoluteExportPaths) {
  // Every path rospack reports is a folder path without the package name in front.
  for (const std::string& path : exportedPaths("gazebo_model_path")) {
    EXPECT_EQ(path[0], '/') << path;
  }
}

TEST_F(Paths, WorldNamesResolveLikeGzserver) {
  const fs::path world = tmp_ / "res" / "worlds" / "empty.world";
  touch(world);
  const Environment env = {{"GAZEBO_RESOURCE_PATH", "/nowhere:" + (tmp_ / "res").string()}};
  EXPECT_EQ(resolveWorld("worlds/empty.world", env, "/"), world.string());
  EXPECT_EQ(resolveWorld(world.string(), {}, "/"), world.string());
  EXPECT_EQ(resolveWorld("res/worlds/empty.world", {}, tmp_.string()), world.string());
  try {
    resolveWorld("worlds/moon.world", env, "/");
    FAIL() << "a missing world resolved";
  } catch (const WorldNotFound& error) {
    EXPECT_EQ(std::string(error.what()),
              "world \"worlds/moon.world\" not found: not a file, and not in "
              "GAZEBO_RESOURCE_PATH (/nowhere, " + (tmp_ / "res").string() + ")");
  }
  EXPECT_THROW(resolveWorld("worlds/moon.world", {}, "/"), WorldNotFound);
}

TEST_F(Paths, AWorldFileStartsTheSimulatorWithoutCrawlingThePackages) {
  const fs::path world = tmp_ / "track.world";
  touch(world);
  const Environment given = {{"GAZEBO_MODEL_PATH", "/mine"}};
  for (const auto& [name, cwd] : {std::make_pair(world.string(), std::string("/")),
                                  std::make_pair(std::string("track.world"), tmp_.string())}) {
    const auto [env, path] = serverEnvironment(name, given, cwd, rospack_);
    EXPECT_EQ(env, given);
    EXPECT_EQ(path, world.string());
  }
  EXPECT_TRUE(rospackCalls().empty());
}

TEST_F(Paths, AWorldNameIsLookedUpWithTheExports) {
  const fs::path world = tmp_ / "media" / "worlds" / "empty.world";
  touch(world);
  const auto [env, path] = serverEnvironment(
      "worlds/empty.world", {{"GAZEBO_RESOURCE_PATH", (tmp_ / "media").string()}}, "/", rospack_);
  EXPECT_EQ(path, world.string());
  EXPECT_EQ(env.at("GAZEBO_MODEL_PATH"), "/a/models:/a/more:/b/models");
  const std::vector<std::string> calls = rospackCalls();
  EXPECT_NE(std::find(calls.begin(), calls.end(), "plugins --attrib=gazebo_media_path gazebo_ros"),
            calls.end());
}

TEST(ServerArgs, EmptyWorldLaunchArguments) {
  // empty_world.launch paused:=true verbose:=true extra_gazebo_args:="--seed 7"
  const ServerArgs args = parseServerArgs({"-u", "", "--verbose", "-e", "ode", "--seed", "7",
                                           "worlds/empty.world", "__name:=gazebo",
                                           "__log:=/tmp/x.log"});
  EXPECT_TRUE(args.paused);
  EXPECT_EQ(args.world, "worlds/empty.world");
  ASSERT_TRUE(args.seed.has_value());
  EXPECT_EQ(*args.seed, 7);
  EXPECT_EQ(args.ignored, std::vector<std::string>({"--verbose"}));
  EXPECT_EQ(nodeArguments(args, "/w/empty.world"),
            std::vector<std::string>({"_world_file:=/w/empty.world", "_paused:=true",
                                      "_seed:=7", "__name:=gazebo", "__log:=/tmp/x.log"}));
}

TEST(ServerArgs, RecordingAndPhysicsAreAccepted) {
  const ServerArgs args = parseServerArgs({"-r", "-e", "bullet", "--record_path", "/tmp/r",
                                           "--minimal_comms", "my.world"});
  EXPECT_FALSE(args.paused);
  EXPECT_EQ(args.physics, "bullet");
  EXPECT_EQ(args.world, "my.world");
  EXPECT_EQ(args.ignored,
            std::vector<std::string>({"-r", "--record_path /tmp/r", "--minimal_comms"}));
  EXPECT_EQ(nodeArguments(args, "/w/my.world"),
            std::vector<std::string>({"_world_file:=/w/my.world", "_paused:=false"}));
}

TEST(ServerArgs, BadValuesAreErrors) {
  try {
    parseServerArgs({"-e"});
    FAIL() << "-e without a value accepted";
  } catch (const ServerArgsError& error) {
    EXPECT_STREQ(error.what(), "gzserver option -e needs a value");
  }
  try {
    parseServerArgs({"--seed", "x7"});
    FAIL() << "--seed x7 accepted";
  } catch (const ServerArgsError& error) {
    EXPECT_STREQ(error.what(), "invalid literal for int() with base 10: 'x7'");
  }
  EXPECT_EQ(*parseServerArgs({"--seed", " -1_2 "}).seed, -12);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
