#ifndef BULLET_SIM_TEST_LOAD_ERRORS_H
#define BULLET_SIM_TEST_LOAD_ERRORS_H

#include <string>

#include "bullet_sim/errors.h"

namespace bullet_sim_test {

/// The path of a file in test/fixtures (one fixture per failure mode).
inline std::string fixture(const std::string& name) {
  return std::string(BULLET_SIM_FIXTURES) + "/" + name;
}

/// Runs `load` and returns the LoadError's message ("" when nothing is thrown).
template <typename F>
std::string loadErrorOf(F load) {
  try {
    load();
  } catch (const bullet_sim::LoadError& e) {
    return e.what();
  }
  return "";
}

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_LOAD_ERRORS_H
