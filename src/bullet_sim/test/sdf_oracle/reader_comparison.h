#ifndef BULLET_SIM_TEST_READER_COMPARISON_H
#define BULLET_SIM_TEST_READER_COMPARISON_H

#include <string>
#include <vector>

#include "bullet_sim/description/resource_paths.h"
#include "description/sdf/sdf_dom.h"
#include "differential_corpus.h"

namespace bullet_sim_test {

/// The folder of the built-in sun and ground_plane the test was built with.
std::string builtinModelsDir();

/// A resolver with the file's model folders only: a run does not depend on the
/// machine's GAZEBO_MODEL_PATH or ROS packages.
bullet_sim::UriResolver resolverFor(const CorpusFile& file);

/// The simulator's reader on `file` (parseSdfXml, then readSdf), its warnings added to
/// `warnings`. @throws bullet_sim::LoadError as the reader does.
bullet_sim::SdfDocument readOurs(const CorpusFile& file, std::vector<std::string>* warnings);

/// What reading one file with both readers found.
struct Comparison {
  /// Each a failure: a field that differs (file, field path, both values), or one reader
  /// refusing a file the other reads.
  std::vector<std::string> differences;
  /// What was not a failure but is worth a line: both refuse the file (and why), or the
  /// inertia check of libsdformat that was set aside.
  std::string note;
  bool compared = false;     ///< both read the file and every field was compared
  bool both_refuse = false;  ///< neither reader reads the file
};

/// Both readers on `file`, compared field by field. Needs the oracle (oracleAvailable).
Comparison compareReaders(const CorpusFile& file);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_READER_COMPARISON_H
