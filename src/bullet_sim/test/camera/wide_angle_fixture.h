#ifndef BULLET_SIM_TEST_WIDE_ANGLE_FIXTURE_H
#define BULLET_SIM_TEST_WIDE_ANGLE_FIXTURE_H

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace bullet_sim_test {

/// test/fixtures/wide_angle_robot.urdf with each `from` replaced by its `to` (the test fails
/// if one is not there).
inline std::string wideAngleFixtureWith(
    std::initializer_list<std::pair<std::string, std::string>> replacements = {}) {
  std::ifstream in(std::string(BULLET_SIM_FIXTURES) + "/wide_angle_robot.urdf");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  for (const auto& [from, to] : replacements) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_WIDE_ANGLE_FIXTURE_H
