// The oracle, on a machine where libsdformat 12 is installed.
#include "oracle_access.h"

#include "reader_comparison.h"

namespace bullet_sim_test {

bool oracleAvailable() { return true; }

OracleResult oracleReading(const CorpusFile& file) {
  return readWithLibsdformat(file.path, resolverFor(file), builtinModelsDir());
}

}  // namespace bullet_sim_test
