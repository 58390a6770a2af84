#include "server_args.h"

#include <regex>
#include <set>

namespace gazebo_ros_server {
namespace {

// Gazebo 11's gzserver options that take a value (--minimal_comms is a flag).
const std::set<std::string> kOptionsWithValue = {
    "-e", "--physics", "-p", "--play", "--record_path", "--record_period", "--record_filter",
    "--record_encoding", "--iters", "-s", "--server-plugin", "-o", "--profile", "--seed"};

/// Python's int() of a --seed value: optional sign, decimal digits with '_' between them,
/// surrounding whitespace.
long long pyInt(const std::string& text) {
  static const std::regex kInt("\\s*[+-]?\\d(_?\\d)*\\s*");
  if (!std::regex_match(text, kInt)) {
    throw ServerArgsError("invalid literal for int() with base 10: '" + text + "'");
  }
  std::string digits;
  for (char c : text) {
    if (c != '_') digits += c;
  }
  try {
    return std::stoll(digits);
  } catch (const std::out_of_range&) {
    throw ServerArgsError("--seed " + text + ": out of range");
  }
}

}  // namespace

ServerArgs parseServerArgs(const std::vector<std::string>& argv) {
  ServerArgs args;
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& word = argv[i];
    if (word.find(":=") != std::string::npos) {
      args.remappings.push_back(word);
    } else if (word == "-u" || word == "--pause") {
      args.paused = true;
    } else if (kOptionsWithValue.count(word)) {
      if (i + 1 >= argv.size()) throw ServerArgsError("gzserver option " + word + " needs a value");
      const std::string& value = argv[++i];
      if (word == "--seed") {
        args.seed = pyInt(value);
      } else if (word == "-e" || word == "--physics") {
        args.physics = value;
      } else {
        args.ignored.push_back(word + " " + value);
      }
    } else if (!word.empty() && word[0] == '-') {
      args.ignored.push_back(word);
    } else if (!word.empty()) {
      args.world = word;
    }
  }
  return args;
}

std::vector<std::string> nodeArguments(const ServerArgs& args, const std::string& world_path) {
  std::vector<std::string> params = {"_world_file:=" + world_path,
                                     std::string("_paused:=") + (args.paused ? "true" : "false")};
  if (args.seed) params.push_back("_seed:=" + std::to_string(*args.seed));
  params.insert(params.end(), args.remappings.begin(), args.remappings.end());
  return params;
}

}  // namespace gazebo_ros_server
