// The simulator's SDF reader against libsdformat 12 on every SDF file of the workspace,
// on fixtures written here (one per version difference and feature) and on the upstream
// clones found through MOBILITY_UPSTREAM_WS: every field of the two readings compared,
// each difference a failure naming the file, the field path and both values.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "differential_corpus.h"
#include "generated_fixtures.h"
#include "oracle_access.h"
#include "reader_comparison.h"
#include "temp_dir.h"

using namespace bullet_sim_test;

namespace {

/// Both readers on every file of `corpus`: a failure per difference, a line per file.
void compareAll(const std::vector<CorpusFile>& corpus) {
  int compared = 0, refused = 0;
  for (const CorpusFile& file : corpus) {
    const Comparison c = compareReaders(file);
    for (const std::string& d : c.differences) ADD_FAILURE() << d;
    compared += c.compared;
    refused += c.both_refuse;
    std::printf("%s %s%s%s\n", c.differences.empty() ? "[same]" : "[DIFF]", file.path.c_str(),
                c.note.empty() ? "" : ": ", c.note.c_str());
  }
  std::printf("%zu files: %d compared field by field, %d refused by both readers\n",
              corpus.size(), compared, refused);
}

std::vector<CorpusFile> generatedCorpus(const TempDir& dir) {
  std::vector<GeneratedFixture> fixtures = versionFixtures();
  for (GeneratedFixture& f : featureFixtures()) fixtures.push_back(std::move(f));
  return writeFixtures(fixtures, dir.path());
}

/// The clones of `kind` (upstreamClones), or a skip saying why there are none.
std::vector<UpstreamClone> clonesOf(const std::string& kind) {
  std::vector<UpstreamClone> out;
  for (const UpstreamClone& c : upstreamClones(BULLET_SIM_WORKSPACE)) {
    if (c.kind == kind) out.push_back(c);
  }
  return out;
}

void compareClones(const std::string& kind) {
  const std::vector<UpstreamClone> clones = clonesOf(kind);
  if (clones.empty()) {
    const char* env = std::getenv("MOBILITY_UPSTREAM_WS");
    GTEST_SKIP() << "no clone of " << kind << " found under MOBILITY_UPSTREAM_WS ('"
                 << (env ? env : "") << "'): its files are not compared";
  }
  if (!oracleAvailable()) GTEST_SKIP() << kNoOracle;
  for (const UpstreamClone& clone : clones) {
    const std::vector<CorpusFile> corpus = cloneCorpus(clone);
    std::printf("%s at %s: %zu files\n", kind.c_str(), clone.root.c_str(), corpus.size());
    EXPECT_FALSE(corpus.empty()) << clone.root << " holds no .world or .sdf file";
    compareAll(corpus);
  }
}

}  // namespace

TEST(SdfDifferential, CorpusHasTheWorkspaceFilesAndTheGeneratedFixtures) {
  const std::vector<CorpusFile> workspace = workspaceCorpus(BULLET_SIM_WORKSPACE);
  TempDir dir;
  const std::vector<CorpusFile> generated = generatedCorpus(dir);
  size_t upstream = 0;
  for (const UpstreamClone& clone : upstreamClones(BULLET_SIM_WORKSPACE)) {
    upstream += cloneCorpus(clone).size();
  }
  std::printf("corpus: %zu workspace files, %zu generated fixtures, %zu upstream files\n",
              workspace.size(), generated.size(), upstream);
  for (const Exclusion& e : workspaceExclusions()) {
    std::printf("left out: %s (%s)\n", e.relative_path.c_str(), e.reason.c_str());
  }
  EXPECT_GE(workspace.size() + generated.size(), 40u);
  EXPECT_GE(generated.size(), 16u);
}

TEST(SdfDifferential, WorkspaceFiles) {
  if (!oracleAvailable()) GTEST_SKIP() << kNoOracle;
  compareAll(workspaceCorpus(BULLET_SIM_WORKSPACE));
}

TEST(SdfDifferential, GeneratedFixtures) {
  if (!oracleAvailable()) GTEST_SKIP() << kNoOracle;
  TempDir dir;
  compareAll(generatedCorpus(dir));
}

TEST(SdfDifferential, TrainingTurtlebot3Simulations) {
  compareClones("training turtlebot3_simulations");
}

TEST(SdfDifferential, RobotisTurtlebot3Simulations) {
  compareClones("ROBOTIS turtlebot3_simulations");
}

TEST(SdfDifferential, GazeboRosPkgsTestWorlds) { compareClones("gazebo_ros_pkgs"); }
