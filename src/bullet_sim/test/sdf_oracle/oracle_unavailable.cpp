// Stands in for the oracle on a machine without libsdformat 12: the tests that need it
// skip, saying so (kNoOracle).
#include <stdexcept>

#include "oracle_access.h"

namespace bullet_sim_test {

bool oracleAvailable() { return false; }

OracleResult oracleReading(const CorpusFile&) { throw std::logic_error(kNoOracle); }

}  // namespace bullet_sim_test
