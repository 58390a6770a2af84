// The comparer's own behaviour: what a difference says, what is not one.
#include <gtest/gtest.h>

#include "dom_compare.h"
#include "plugin_params.h"

using namespace bullet_sim;
using namespace bullet_sim_test;

namespace {

/// A world with a ground plane whose collision is a box of `size`.
SdfDocument groundWorld(const Eigen::Vector3d& size) {
  SdfCollision collision;
  collision.name = "collision";
  collision.geometry.type = "box";
  collision.geometry.shape = Geometry::box(size.x(), size.y(), size.z());
  SdfLink link;
  link.name = "link";
  link.collisions.push_back(collision);
  SdfModel model;
  model.name = "ground_plane";
  model.links.push_back(link);
  SdfDocument doc;
  doc.world = SdfWorld();
  doc.world->models.push_back(model);
  return doc;
}

/// The differences of two such worlds; the ground plane's canonical link is its link.
std::vector<std::string> differences(const SdfDocument& a, const SdfDocument& b) {
  DomComparer cmp("f.world");
  compareDocuments(&cmp, a, b, {{"world.models[ground_plane]", {"link", Eigen::Isometry3d::Identity()}}});
  return cmp.differences();
}

}  // namespace

TEST(DomComparer, NamesTheFileTheFieldPathAndBothValues) {
  const auto d = differences(groundWorld({1, 1, 1}), groundWorld({100, 100, 0.5}));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0],
            "f.world: world.models[ground_plane].links[link].collisions[collision].geometry"
            ".shape.size: ours '1 1 1', libsdformat '100 100 0.5'");
}

TEST(DomComparer, SameReadingsHaveNoDifference) {
  EXPECT_TRUE(differences(groundWorld({1, 2, 3}), groundWorld({1, 2, 3})).empty());
}

TEST(DomComparer, PosesDifferBeyondOneNanometre) {
  SdfDocument a = groundWorld({1, 1, 1}), b = a;
  b.world->models[0].T_parent_model.translation().x() = 5e-10;
  EXPECT_TRUE(differences(a, b).empty());
  b.world->models[0].T_parent_model.translation().x() = 2e-9;
  const auto d = differences(a, b);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d[0].find("world.models[ground_plane].T_parent_model: ours 'xyz (0 0 0) rpy (0 0 0)', "
                      "libsdformat 'xyz (2e-09 0 0) rpy (0 0 0)'"),
            std::string::npos)
      << d[0];
}

TEST(DomComparer, AnItemOnlyOneSideHasIsADifference) {
  SdfDocument a = groundWorld({1, 1, 1}), b = a;
  b.world->models[0].name = "ground";
  const auto d = differences(a, b);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], "f.world: world.models[ground_plane]: ours 'present', libsdformat 'absent'");
  EXPECT_EQ(d[1], "f.world: world.models[ground]: ours 'absent', libsdformat 'present'");
}

TEST(DomComparer, PluginParametersAreComparedByNameNotByPrinting) {
  SdfPlugin ours{"drive", "libdrive.so",
                 "<plugin name=\"drive\" filename=\"libdrive.so\">\n"
                 "  <wheelSeparation> 0.16 </wheelSeparation><ros><namespace>/a</namespace></ros>\n"
                 "</plugin>"};
  SdfPlugin theirs = ours;
  theirs.xml = "<plugin name='drive' filename='libdrive.so'><wheelSeparation>0.16"
               "</wheelSeparation><ros><namespace>/b</namespace></ros></plugin>";
  DomComparer cmp("f.world");
  comparePlugins(&cmp, "plugins", {ours}, {theirs});
  ASSERT_EQ(cmp.differences().size(), 1u);
  EXPECT_EQ(cmp.differences()[0],
            "f.world: plugins[drive].parameters[ros/namespace]: ours '/a', libsdformat '/b'");
}

TEST(PluginParameters, PathsOfNestedChildrenAndAttributes) {
  std::string problem;
  const auto p = pluginParameters(
      "<plugin name='p' filename='f'><a>1</a><ros><remapping from='x'>y</remapping></ros></plugin>",
      &problem);
  EXPECT_EQ(problem, "");
  const std::vector<PluginParameter> expected = {
      {"a", "1"}, {"ros/remapping@from", "x"}, {"ros/remapping", "y"}};
  EXPECT_EQ(p, expected);
}
