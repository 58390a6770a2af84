// The generated C++ types of turtlebot3_msgs are those of the Noetic release: md5sums,
// type names and constants compared with released_types.txt (the values ROBOTIS publishes).
// No master is needed: message traits are compile-time facts of the generated headers.
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <ros/message_traits.h>
#include <turtlebot3_msgs/SensorState.h>
#include <turtlebot3_msgs/Sound.h>
#include <turtlebot3_msgs/VersionInfo.h>

namespace {

struct Line {
  std::vector<std::string> words;
  int number;
};

// The non-comment lines of released_types.txt that start with `kind`, split into words.
std::vector<Line> releasedLines(const std::string& kind) {
  std::ifstream source(RELEASED_TYPES);
  EXPECT_TRUE(source.good()) << RELEASED_TYPES << ": cannot open";
  std::vector<Line> lines;
  std::string text;
  for (int number = 1; std::getline(source, text); ++number) {
    std::istringstream words(text.substr(0, text.find('#')));
    Line line{{}, number};
    for (std::string word; words >> word;) line.words.push_back(word);
    if (!line.words.empty() && line.words[0] == kind) lines.push_back(line);
  }
  return lines;
}

template <class M>
std::pair<std::string, std::string> traitsOf() {
  return {ros::message_traits::DataType<M>::value(), ros::message_traits::MD5Sum<M>::value()};
}

// Type name -> (DataType, MD5Sum) as the generated headers state them.
const std::map<std::string, std::pair<std::string, std::string>> kTraits = {
    {"SensorState", traitsOf<turtlebot3_msgs::SensorState>()},
    {"VersionInfo", traitsOf<turtlebot3_msgs::VersionInfo>()},
    {"Sound", traitsOf<turtlebot3_msgs::Sound>()},
};

// "Type.CONSTANT" -> value of the generated constant.
const std::map<std::string, int> kConstants = {
    {"SensorState.BUMPER_FORWARD", turtlebot3_msgs::SensorState::BUMPER_FORWARD},
    {"SensorState.BUMPER_BACKWARD", turtlebot3_msgs::SensorState::BUMPER_BACKWARD},
    {"SensorState.CLIFF", turtlebot3_msgs::SensorState::CLIFF},
    {"SensorState.SONAR", turtlebot3_msgs::SensorState::SONAR},
    {"SensorState.ILLUMINATION", turtlebot3_msgs::SensorState::ILLUMINATION},
    {"SensorState.BUTTON0", turtlebot3_msgs::SensorState::BUTTON0},
    {"SensorState.BUTTON1", turtlebot3_msgs::SensorState::BUTTON1},
    {"SensorState.ERROR_LEFT_MOTOR", turtlebot3_msgs::SensorState::ERROR_LEFT_MOTOR},
    {"SensorState.ERROR_RIGHT_MOTOR", turtlebot3_msgs::SensorState::ERROR_RIGHT_MOTOR},
    {"SensorState.TORQUE_ON", turtlebot3_msgs::SensorState::TORQUE_ON},
    {"SensorState.TORQUE_OFF", turtlebot3_msgs::SensorState::TORQUE_OFF},
    {"Sound.OFF", turtlebot3_msgs::Sound::OFF},
    {"Sound.ON", turtlebot3_msgs::Sound::ON},
    {"Sound.LOW_BATTERY", turtlebot3_msgs::Sound::LOW_BATTERY},
    {"Sound.ERROR", turtlebot3_msgs::Sound::ERROR},
    {"Sound.BUTTON1", turtlebot3_msgs::Sound::BUTTON1},
    {"Sound.BUTTON2", turtlebot3_msgs::Sound::BUTTON2},
};

TEST(Turtlebot3MsgsCpp, EveryTypeHasTheReleasedMd5sum) {
  const auto lines = releasedLines("md5");
  ASSERT_EQ(lines.size(), kTraits.size()) << RELEASED_TYPES << ": md5 lines";
  for (const auto& line : lines) {
    ASSERT_EQ(line.words.size(), 3u) << RELEASED_TYPES << ":" << line.number;
    const auto traits = kTraits.find(line.words[1]);
    ASSERT_NE(traits, kTraits.end()) << "no C++ type " << line.words[1];
    EXPECT_EQ(traits->second.first, "turtlebot3_msgs/" + line.words[1]);
    EXPECT_EQ(traits->second.second, line.words[2]) << line.words[1];
  }
}

TEST(Turtlebot3MsgsCpp, ConstantsHaveTheReleasedValues) {
  const auto lines = releasedLines("const");
  ASSERT_EQ(lines.size(), kConstants.size()) << RELEASED_TYPES << ": const lines";
  for (const auto& line : lines) {
    ASSERT_EQ(line.words.size(), 4u) << RELEASED_TYPES << ":" << line.number;
    const auto constant = kConstants.find(line.words[1] + "." + line.words[2]);
    ASSERT_NE(constant, kConstants.end()) << "no C++ constant " << line.words[2];
    EXPECT_EQ(constant->second, std::stoi(line.words[3])) << line.words[1] << "." << line.words[2];
  }
}

// Wire size of a SensorState with an empty frame_id, counted by hand from the released
// fields: header 4 (seq) + 8 (stamp) + 4 (frame_id length); bumper, led, button, torque
// 1 each; cliff, sonar, illumination, battery 4 each; two int32 encoders.
TEST(Turtlebot3MsgsCpp, SensorStateSerialisesToTheReleasedSize) {
  turtlebot3_msgs::SensorState state;
  EXPECT_EQ(ros::serialization::serializationLength(state), 16u + 4u + 16u + 8u);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
