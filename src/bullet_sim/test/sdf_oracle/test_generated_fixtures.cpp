// The generated fixtures' hand-worked values, asserted on each reader on its own (so that
// the differential test does not rest on the two readers agreeing), and the one intended
// difference between them: Gazebo classic's reading of the <script> shorthand.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bullet_sim/errors.h"
#include "generated_fixtures.h"
#include "oracle_access.h"
#include "reader_comparison.h"
#include "temp_dir.h"

using namespace bullet_sim_test;
using bullet_sim::SdfDocument;

namespace {

std::vector<GeneratedFixture> allFixtures() {
  std::vector<GeneratedFixture> fixtures = versionFixtures();
  for (GeneratedFixture& f : featureFixtures()) fixtures.push_back(std::move(f));
  return fixtures;
}

/// Each fixture written, read by `read` (which calls `check` with its reading) and
/// checked against its hand-worked values.
template <class Read>
void checkEveryFixture(const std::string& reader, Read read) {
  TempDir dir;
  const std::vector<GeneratedFixture> fixtures = allFixtures();
  const std::vector<CorpusFile> files = writeFixtures(fixtures, dir.path());
  for (size_t i = 0; i < fixtures.size(); ++i) {
    SCOPED_TRACE(reader + " reading " + fixtures[i].name);
    try {
      read(files[i], fixtures[i].check);
    } catch (const std::exception& e) {
      ADD_FAILURE() << fixtures[i].name << ": " << e.what();
    }
  }
}

using Check = std::function<void(const SdfDocument&, const CanonicalOf&)>;

}  // namespace

TEST(SdfGeneratedFixtures, OurReaderGivesTheHandWorkedValues) {
  checkEveryFixture("ours", [](const CorpusFile& file, const Check& check) {
    std::vector<std::string> warnings;
    check(readOurs(file, &warnings),
          [](const std::string&, const bullet_sim::SdfModel& m) { return m.canonicalLink(); });
  });
}

TEST(SdfGeneratedFixtures, LibsdformatGivesTheHandWorkedValues) {
  if (!oracleAvailable()) GTEST_SKIP() << kNoOracle;
  checkEveryFixture("libsdformat", [](const CorpusFile& file, const Check& check) {
    const OracleResult result = oracleReading(file);
    for (const std::string& e : result.errors) ADD_FAILURE() << "libsdformat: " << e;
    check(result.document, [&](const std::string& path, const bullet_sim::SdfModel&) {
      std::optional<std::pair<std::string, Eigen::Isometry3d>> picked;
      const auto found = result.canonical_links.find(path);
      if (found != result.canonical_links.end()) {
        picked.emplace(found->second.scoped_name, found->second.T_model_link);
      }
      return picked;
    });
  });
}

// <script>Gazebo/Green</script> names the material without <uri> and <name>. Gazebo
// classic reads it: sdformat 9 adds the missing required children with their default
// "__default__", and Visual::SetMaterial ignores that name, so the visual keeps its
// default look. libsdformat 12 refuses the file. Ours follows Gazebo classic: no script
// name, and a warning.
TEST(SdfKnownDifferences, ScriptShorthandIsReadAsGazeboClassicReadsIt) {
  TempDir dir;
  const std::string path = dir.write("shorthand.world", sdfText("1.6", R"(<world name="w">
  <model name="m"><static>true</static><link name="link"><visual name="v">
    <geometry><box><size>1 1 1</size></box></geometry>
    <material><script>Gazebo/Green</script></material>
  </visual></link></model></world>)"));
  const CorpusFile file{path, {}};
  std::vector<std::string> warnings;
  const SdfDocument ours = readOurs(file, &warnings);
  const bullet_sim::SdfMaterial& material = need(
      need(need(need(need(ours.world, "world").models, "m").links, "link").visuals, "v").material,
      "<material>");
  EXPECT_EQ(material.script_name, "");
  EXPECT_TRUE(material.script_uris.empty());
  ASSERT_EQ(warnings.size(), 1u) << "one warning for the shorthand";
  EXPECT_NE(warnings.front().find("script"), std::string::npos) << warnings.front();
  if (!oracleAvailable()) GTEST_SKIP() << kNoOracle << " (our reading was checked)";
  const OracleResult theirs = oracleReading(file);
  ASSERT_EQ(theirs.set_aside.size(), 2u) << "libsdformat 12: no <uri>, no <name>";
  EXPECT_NE(theirs.set_aside[0].find("A <script> element is missing a child <uri> element"),
            std::string::npos)
      << theirs.set_aside[0];
  EXPECT_NE(theirs.set_aside[1].find("A <script> element is missing a child <name> element"),
            std::string::npos)
      << theirs.set_aside[1];
  const Comparison same = compareReaders(file);
  EXPECT_TRUE(same.compared && same.differences.empty())
      << "past its errors, libsdformat reads the shorthand as ours does: no script name";
}
