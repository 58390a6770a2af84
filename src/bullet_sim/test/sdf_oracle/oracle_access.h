#ifndef BULLET_SIM_TEST_ORACLE_ACCESS_H
#define BULLET_SIM_TEST_ORACLE_ACCESS_H

#include "differential_corpus.h"
#include "sdformat_oracle.h"

namespace bullet_sim_test {

/// Why the comparisons are skipped on a machine without the oracle.
constexpr const char* kNoOracle =
    "libsdformat 12 is not installed: the differential test needs it as its oracle";

/// True when the test was built with libsdformat 12 (oracle_access.cpp), false when not
/// (oracle_unavailable.cpp): CMake compiles one of the two.
bool oracleAvailable();

/// libsdformat's reading of `file`, its includes looked up in the file's model folders.
/// @throws std::logic_error without the oracle.
OracleResult oracleReading(const CorpusFile& file);

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_ORACLE_ACCESS_H
