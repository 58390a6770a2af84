// The world file on bullet_sim_node's command line, read before ros::init so that the
// world is parsed while roscpp starts: the `_world_file:=PATH` that gzserver passes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config.h"

namespace {

std::string worldOf(std::vector<const char*> args) {
  args.insert(args.begin(), "bullet_sim_node");
  return bullet_sim_node::commandLineWorldFile(static_cast<int>(args.size()), args.data());
}

TEST(CommandLineWorld, TheWorldFileGzserverPasses) {
  EXPECT_EQ(worldOf({"_world_file:=/w/round track.world", "_paused:=false", "__name:=gazebo"}),
            "/w/round track.world");
}

TEST(CommandLineWorld, NoneWhenNotThere) {
  EXPECT_EQ(worldOf({}), "");
  EXPECT_EQ(worldOf({"__name:=gazebo", "_paused:=true"}), "");
}

TEST(CommandLineWorld, OnlyThePrivateParameter) {
  // A remapping of the name world_file, or a parameter with a longer name, is not it.
  EXPECT_EQ(worldOf({"world_file:=/a.world", "_world_file_2:=/b.world", "_world_file"}), "");
}

TEST(CommandLineWorld, TheLastOneCountsAsForRoscpp) {
  EXPECT_EQ(worldOf({"_world_file:=/a.world", "_world_file:=/b.world"}), "/b.world");
}

TEST(CommandLineWorld, ValueKeepsItsSeparators) {
  EXPECT_EQ(worldOf({"_world_file:=/x/a:=b.world"}), "/x/a:=b.world");
}

}  // namespace
