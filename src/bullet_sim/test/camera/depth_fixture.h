#ifndef BULLET_SIM_TEST_DEPTH_FIXTURE_H
#define BULLET_SIM_TEST_DEPTH_FIXTURE_H

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace bullet_sim_test {

/// The text of test/fixtures/depth_camera_robot.urdf (a robot with one Kinect-style camera).
inline std::string depthFixtureText() {
  std::ifstream in(std::string(BULLET_SIM_FIXTURES) + "/depth_camera_robot.urdf");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// That fixture with one piece of text replaced (the test fails if it is not there).
inline std::string depthFixtureWith(const std::string& from, const std::string& to) {
  std::string text = depthFixtureText();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_DEPTH_FIXTURE_H
