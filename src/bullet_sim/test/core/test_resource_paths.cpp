// UriResolver tests: model://, package://, file://, absolute and relative URIs against
// folders the tests build in a temp dir.
#include <cstdlib>
#include <future>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/description/resource_paths.h"
#include "temp_dir.h"

using bullet_sim::ResourcePaths;
using bullet_sim::UriResolver;
using bullet_sim_test::TempDir;

namespace {

const char* kManifest = "<?xml version=\"1.0\"?>\n<package format=\"2\"><name>%s</name></package>\n";

std::string manifest(const std::string& name) {
  std::string text = kManifest;
  return text.replace(text.find("%s"), 2, name);
}

}  // namespace

TEST(UriResolver, ModelUrisSearchTheModelFoldersInOrder) {
  TempDir dir;
  dir.write("first/table/model.config", "<model/>");
  dir.write("second/table/model.config", "<model/>");
  dir.write("second/table/meshes/top.stl", "solid");
  dir.write("second/lamp/model.config", "<model/>");
  const UriResolver resolver(ResourcePaths{{dir.sub("first"), dir.sub("second")}, {}});

  EXPECT_EQ(resolver.resolve("model://table/model.config", ""), dir.sub("first/table/model.config"));
  // A file only the second folder's copy has is found there.
  EXPECT_EQ(resolver.resolve("model://table/meshes/top.stl", ""),
            dir.sub("second/table/meshes/top.stl"));
  EXPECT_EQ(resolver.findModel("table"), dir.sub("first/table"));
  EXPECT_EQ(resolver.findModel("lamp"), dir.sub("second/lamp"));

  std::vector<std::string> searched;
  EXPECT_EQ(resolver.findModel("chair", &searched), "");
  EXPECT_EQ(searched, (std::vector<std::string>{dir.sub("first"), dir.sub("second")}));
  searched.clear();
  EXPECT_EQ(resolver.resolve("model://chair/model.config", "", &searched), "");
  EXPECT_EQ(searched.size(), 2u);
}

/// Later model paths that record whether anyone asked for them (a deferred future runs
/// its function in the first get()).
std::shared_future<std::vector<std::string>> laterPaths(std::vector<std::string> paths,
                                                        bool* asked) {
  return std::async(std::launch::deferred, [paths, asked] {
           *asked = true;
           return paths;
         })
      .share();
}

TEST(UriResolver, LaterModelPathsAreWaitedForOnlyWhenTheFirstOnesFail) {
  TempDir dir;
  dir.write("env/table/model.config", "<model/>");
  dir.write("exported/table/model.config", "<model/>");
  dir.write("exported/lamp/meshes/lamp.stl", "solid");
  bool asked = false;
  ResourcePaths paths{{dir.sub("env")}, {}};
  // An exported folder that the environment already lists is not searched twice.
  paths.later_model_paths = laterPaths({dir.sub("env"), dir.sub("exported")}, &asked);
  const UriResolver resolver(paths);

  EXPECT_EQ(resolver.findModel("table"), dir.sub("env/table"));
  EXPECT_EQ(resolver.resolve("model://table/model.config", ""), dir.sub("env/table/model.config"));
  EXPECT_FALSE(asked);

  EXPECT_EQ(resolver.resolve("model://lamp/meshes/lamp.stl", ""),
            dir.sub("exported/lamp/meshes/lamp.stl"));
  EXPECT_TRUE(asked);
  EXPECT_EQ(resolver.findModel("lamp"), dir.sub("exported/lamp"));
  std::vector<std::string> searched;
  EXPECT_EQ(resolver.findModel("chair", &searched), "");
  EXPECT_EQ(searched, (std::vector<std::string>{dir.sub("env"), dir.sub("exported")}));
}

TEST(ResourcePaths, FromEnvironmentSearchesTheExportedModelPathsLast) {
  TempDir dir;
  dir.write("exported/lamp/model.config", "<model/>");
  bool asked = false;
  ResourcePaths::setExportedModelPaths(laterPaths({dir.sub("exported")}, &asked));
  setenv("GAZEBO_MODEL_PATH", "/nowhere", 1);
  const UriResolver resolver(ResourcePaths::fromEnvironment());
  std::vector<std::string> searched;
  EXPECT_EQ(resolver.findModel("lamp", &searched), dir.sub("exported/lamp"));
  EXPECT_EQ(searched, (std::vector<std::string>{"/nowhere", dir.sub("exported")}));
  ResourcePaths::setExportedModelPaths({});
  unsetenv("GAZEBO_MODEL_PATH");
  EXPECT_FALSE(ResourcePaths::fromEnvironment().later_model_paths.valid());
}

TEST(UriResolver, PackageUrisFindPackagesAsRospackCrawls) {
  TempDir dir;
  dir.write("ws/src/robot_description/package.xml", manifest("robot_description"));
  dir.write("ws/src/robot_description/meshes/base.stl", "solid");
  // A package inside a package is not found (rospack does not descend into packages).
  dir.write("ws/src/robot_description/inner/package.xml", manifest("inner_pkg"));
  dir.write("ws/src/robot_description/inner/a.txt", "a");
  // Folders with CATKIN_IGNORE are skipped.
  dir.write("ws/src/ignored/CATKIN_IGNORE", "");
  dir.write("ws/src/ignored/hidden_pkg/package.xml", manifest("hidden_pkg"));
  // The folder name does not matter, package.xml's <name> does.
  dir.write("ws/src/folder_name/package.xml", manifest("real_name"));
  const UriResolver resolver(ResourcePaths{{}, {dir.sub("ws/src")}});

  EXPECT_EQ(resolver.resolve("package://robot_description/meshes/base.stl", ""),
            dir.sub("ws/src/robot_description/meshes/base.stl"));
  EXPECT_EQ(resolver.findPackage("robot_description"), dir.sub("ws/src/robot_description"));
  EXPECT_EQ(resolver.findPackage("inner_pkg"), "");
  EXPECT_EQ(resolver.findPackage("hidden_pkg"), "");
  EXPECT_EQ(resolver.findPackage("real_name"), dir.sub("ws/src/folder_name"));
  EXPECT_EQ(resolver.findPackage("folder_name"), "");
  EXPECT_EQ(resolver.resolve("package://robot_description/meshes/missing.stl", ""), "");
  std::vector<std::string> searched;
  EXPECT_EQ(resolver.resolve("package://no_such_pkg/a.stl", "", &searched), "");
  EXPECT_EQ(searched, std::vector<std::string>{dir.sub("ws/src")});
}

TEST(UriResolver, FileAbsoluteAndRelativePaths) {
  TempDir dir;
  const std::string mesh = dir.write("robot/meshes/wheel.dae", "<COLLADA/>");
  const UriResolver resolver(ResourcePaths{});

  EXPECT_EQ(resolver.resolve("file://" + mesh, ""), mesh);
  EXPECT_EQ(resolver.resolve(mesh, ""), mesh);
  EXPECT_EQ(resolver.resolve("meshes/wheel.dae", dir.sub("robot")), dir.sub("robot/meshes/wheel.dae"));
  std::vector<std::string> searched;
  EXPECT_EQ(resolver.resolve("meshes/tyre.dae", dir.sub("robot"), &searched), "");
  EXPECT_EQ(searched, std::vector<std::string>{dir.sub("robot/meshes")});
  // A folder is not a file.
  EXPECT_EQ(resolver.resolve(dir.sub("robot/meshes"), ""), "");
}

TEST(ResourcePaths, FromEnvironmentSplitsAndSkipsEmptyEntries) {
  setenv("GAZEBO_MODEL_PATH", "/a/models::/b/models:", 1);
  setenv("ROS_PACKAGE_PATH", "/ws/src", 1);
  const ResourcePaths paths = ResourcePaths::fromEnvironment();
  EXPECT_EQ(paths.model_paths, (std::vector<std::string>{"/a/models", "/b/models"}));
  EXPECT_EQ(paths.package_paths, std::vector<std::string>{"/ws/src"});
  unsetenv("GAZEBO_MODEL_PATH");
  EXPECT_TRUE(ResourcePaths::fromEnvironment().model_paths.empty());
}
