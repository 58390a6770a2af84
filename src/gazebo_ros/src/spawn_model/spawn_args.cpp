#include "spawn_args.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>

namespace gazebo_ros_spawn {
namespace {

const char kUsage[] =
    "usage: spawn_model [-h] (-urdf | -sdf)\n"
    "                   (-file FILE_NAME | -param PARAM_NAME | -database MODEL_NAME | -stdin)\n"
    "                   -model MODEL_NAME [-reference_frame REFERENCE_FRAME]\n"
    "                   [-gazebo_namespace GAZEBO_NAMESPACE]\n"
    "                   [-robot_namespace ROBOT_NAMESPACE] [-unpause]\n"
    "                   [-wait MODEL_NAME] [-x X] [-y Y] [-z Z] [-R R] [-P P]\n"
    "                   [-Y Y] [-J JOINT_NAME JOINT_POSITION] [-package_to_model]\n"
    "                   [-b]\n";

const char kOptions[] =
    "\n"
    "Spawns a model (URDF or SDF) in the simulation.\n"
    "\n"
    "options:\n"
    "  -h, --help            show this help message and exit\n"
    "  -urdf                 the model is URDF\n"
    "  -sdf                  the model is SDF\n"
    "  -file FILE_NAME       read the model from a file\n"
    "  -param PARAM_NAME     read the model from a parameter\n"
    "  -database MODEL_NAME  Gazebo's online model database (not reachable here)\n"
    "  -stdin                read the model from stdin\n"
    "  -model MODEL_NAME     name of the model\n"
    "  -reference_frame REFERENCE_FRAME\n"
    "                        frame of the initial pose: \"\" or world, a model or\n"
    "                        model::link\n"
    "  -gazebo_namespace GAZEBO_NAMESPACE\n"
    "                        namespace of the simulator services (default /gazebo)\n"
    "  -robot_namespace ROBOT_NAMESPACE\n"
    "                        namespace of the model's topics (default: this node's)\n"
    "  -unpause              unpause physics after spawning\n"
    "  -wait MODEL_NAME      wait until MODEL_NAME exists before spawning\n"
    "  -x X                  x of the initial position, m\n"
    "  -y Y                  y of the initial position, m\n"
    "  -z Z                  z of the initial position, m\n"
    "  -R R                  roll of the initial orientation, rad\n"
    "  -P P                  pitch of the initial orientation, rad\n"
    "  -Y Y                  yaw of the initial orientation, rad\n"
    "  -J JOINT_NAME JOINT_POSITION\n"
    "                        initial joint position (repeatable)\n"
    "  -package_to_model     turn package:// URIs into model:// ones\n"
    "  -b                    delete the model when this node is stopped\n";

enum class Act { Help, Urdf, Sdf, File, Param, Database, Stdin, Model, ReferenceFrame,
                 GazeboNamespace, RobotNamespace, Unpause, Wait, X, Y, Z, Roll, Pitch, Yaw,
                 Joint, PackageToModel, Bond, Unknown };

struct Option {
  const char* text;
  Act act;
};

// In the order argparse registered them (its messages list matches in this order).
const Option kOptionTable[] = {
    {"-h", Act::Help}, {"--help", Act::Help}, {"-urdf", Act::Urdf}, {"-sdf", Act::Sdf},
    {"-file", Act::File}, {"-param", Act::Param}, {"-database", Act::Database},
    {"-stdin", Act::Stdin}, {"-model", Act::Model}, {"-reference_frame", Act::ReferenceFrame},
    {"-gazebo_namespace", Act::GazeboNamespace}, {"-robot_namespace", Act::RobotNamespace},
    {"-unpause", Act::Unpause}, {"-wait", Act::Wait}, {"-x", Act::X}, {"-y", Act::Y},
    {"-z", Act::Z}, {"-R", Act::Roll}, {"-P", Act::Pitch}, {"-Y", Act::Yaw},
    {"-J", Act::Joint}, {"-package_to_model", Act::PackageToModel}, {"-b", Act::Bond},
};

const std::vector<Act> kFormatGroup = {Act::Urdf, Act::Sdf};
const std::vector<Act> kSourceGroup = {Act::File, Act::Param, Act::Database, Act::Stdin};

/// argparse's name of an action: its option strings joined by '/'.
std::string actionName(Act act) {
  std::string name;
  for (const Option& o : kOptionTable) {
    if (o.act == act) name += (name.empty() ? "" : "/") + std::string(o.text);
  }
  return name;
}

int nargs(Act act) {
  switch (act) {
    case Act::Help: case Act::Urdf: case Act::Sdf: case Act::Stdin: case Act::Unpause:
    case Act::PackageToModel: case Act::Bond:
      return 0;
    case Act::Joint:
      return 2;
    default:
      return 1;
  }
}

const Option* exactOption(const std::string& text) {
  for (const Option& o : kOptionTable) {
    if (text == o.text) return &o;
  }
  return nullptr;
}

[[noreturn]] void fail(const std::string& message) {
  throw UsageError(std::string(kUsage) + "spawn_model: error: " + message);
}

/// Python's repr() of a string, as argparse quotes values in its messages.
std::string pyRepr(const std::string& s) {
  const char quote = s.find('\'') != std::string::npos && s.find('"') == std::string::npos
                         ? '"' : '\'';
  std::string out(1, quote);
  for (char c : s) {
    if (c == '\\' || c == quote) out += '\\';
    out += c;
  }
  return out + quote;
}

/// How argparse reads one command-line word.
struct Word {
  bool option = false;      ///< 'O' (an option, known or not) or 'A' (a value)
  Act act = Act::Unknown;
  std::string option_text;  ///< the option as matched ("-model" for "-mod")
  bool has_explicit = false;
  std::string explicit_value;  ///< "1" of "-x=1" or "-x1"
};

Word classify(const std::string& word, bool after_double_dash) {
  Word w;
  if (after_double_dash || word.size() < 2 || word[0] != '-') return w;
  w.option = true;
  if (const Option* o = exactOption(word)) {
    w.act = o->act;
    w.option_text = o->text;
    return w;
  }
  const size_t eq = word.find('=');
  if (eq != std::string::npos) {
    if (const Option* o = exactOption(word.substr(0, eq))) {
      w.act = o->act;
      w.option_text = o->text;
      w.has_explicit = true;
      w.explicit_value = word.substr(eq + 1);
      return w;
    }
  }
  // Unique prefixes ("-mod"), and a one-letter option with its value attached ("-x1").
  std::vector<Word> matches;
  const bool long_form = word[1] == '-';
  std::string prefix = word;
  if (long_form && eq != std::string::npos) prefix = word.substr(0, eq);
  for (const Option& o : kOptionTable) {
    Word m = w;
    m.act = o.act;
    m.option_text = o.text;
    if (!long_form && word.compare(0, 2, o.text) == 0 && std::string(o.text).size() == 2) {
      m.has_explicit = true;
      m.explicit_value = word.substr(2);
      matches.push_back(m);
    } else if (std::string(o.text).compare(0, prefix.size(), prefix) == 0) {
      if (long_form && eq != std::string::npos) {
        m.has_explicit = true;
        m.explicit_value = word.substr(eq + 1);
      }
      matches.push_back(m);
    }
  }
  if (matches.size() > 1) {
    std::string names;
    for (const Word& m : matches) names += (names.empty() ? "" : ", ") + m.option_text;
    fail("ambiguous option: " + (long_form && eq != std::string::npos ? prefix : word) +
         " could match " + names);
  }
  if (matches.size() == 1) return matches[0];
  static const std::regex kNegativeNumber("^-\\d+$|^-\\d*\\.\\d+$");
  if (std::regex_match(word, kNegativeNumber) || word.find(' ') != std::string::npos) {
    return Word();
  }
  w.option_text = word;
  return w;
}

/// Python's float(): decimal digits with optional '_' between them, an exponent,
/// inf/infinity/nan in any case, surrounding whitespace; nothing else (no hex).
bool pyFloat(const std::string& text, double* value) {
  static const std::regex kFloat(
      "\\s*[+-]?(((\\d(_?\\d)*)(\\.(\\d(_?\\d)*)?)?|\\.\\d(_?\\d)*)([eE][+-]?\\d(_?\\d)*)?"
      "|[iI][nN][fF]([iI][nN][iI][tT][yY])?|[nN][aA][nN])\\s*");
  if (!std::regex_match(text, kFloat)) return false;
  std::string plain;
  for (char c : text) {
    if (c != '_') plain += c;
  }
  *value = std::strtod(plain.c_str(), nullptr);
  return true;
}

/// Python's str() of a float that is not finite.
std::string pyNonFinite(double v) {
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

class Parser {
 public:
  explicit Parser(const std::vector<std::string>& argv) {
    bool double_dash = false;
    for (const std::string& word : argv) {
      if (word.find(":=") != std::string::npos) continue;  // a ROS remapping
      const bool first_double_dash = !double_dash && word == "--";
      if (first_double_dash) dashes_.insert(words_.size());
      words_.push_back(word);
      kinds_.push_back(classify(word, double_dash || first_double_dash));
      double_dash = double_dash || first_double_dash;
    }
  }

  SpawnArgs parse() {
    for (size_t i = 0; i < words_.size();) {
      if (!kinds_[i].option) {
        extras_.push_back(words_[i++]);
        continue;
      }
      i = consumeOption(i);
    }
    checkRequired();
    if (!extras_.empty()) {
      std::string words;
      for (const std::string& e : extras_) words += (words.empty() ? "" : " ") + e;
      fail("unrecognized arguments: " + words);
    }
    return args_;
  }

 private:
  /// One option and its values, from word i; returns the index of the next word. Grouped
  /// one-letter flags ("-bu") are all read before any of them is taken, as argparse does.
  size_t consumeOption(size_t i) {
    Word w = kinds_[i];
    if (w.act == Act::Unknown) {
      extras_.push_back(words_[i]);
      return i + 1;
    }
    std::vector<std::pair<Act, std::vector<std::string>>> taken;
    size_t next = i + 1;
    while (w.has_explicit) {
      const int n = nargs(w.act);
      if (n == 1) {
        taken.push_back({w.act, {w.explicit_value}});
        break;
      }
      if (n == 0 && !w.explicit_value.empty() && w.option_text[1] != '-') {
        taken.push_back({w.act, {}});
        const Option* flag = exactOption(std::string("-") + w.explicit_value[0]);
        if (!flag) fail("argument " + actionName(w.act) + ": ignored explicit argument " +
                        pyRepr(w.explicit_value));
        w.act = flag->act;
        w.option_text = flag->text;
        w.explicit_value = w.explicit_value.substr(1);
        w.has_explicit = !w.explicit_value.empty();
        if (!w.has_explicit) taken.push_back({w.act, values(w.act, &next)});
        continue;
      }
      if (n == 2) fail("argument " + actionName(w.act) + ": expected 2 arguments");
      fail("argument " + actionName(w.act) + ": ignored explicit argument " +
           pyRepr(w.explicit_value));
    }
    if (taken.empty()) taken.push_back({w.act, values(w.act, &next)});
    for (const auto& t : taken) take(t.first, t.second);
    return next;
  }

  /// The values of `act` from word *next on; *next moves past them. They end at the next
  /// option or at "--".
  std::vector<std::string> values(Act act, size_t* next) {
    std::vector<std::string> found;
    while (static_cast<int>(found.size()) < nargs(act) && *next < words_.size() &&
           !kinds_[*next].option && !dashes_.count(*next)) {
      found.push_back(words_[(*next)++]);
    }
    if (static_cast<int>(found.size()) < nargs(act)) {
      fail("argument " + actionName(act) + ": " +
           (nargs(act) == 1 ? "expected one argument" : "expected 2 arguments"));
    }
    return found;
  }

  void take(Act act, const std::vector<std::string>& values) {
    seen_.insert(act);
    for (const std::vector<Act>* group : {&kFormatGroup, &kSourceGroup}) {
      if (std::find(group->begin(), group->end(), act) == group->end()) continue;
      for (Act other : *group) {
        if (other != act && seen_.count(other)) {
          fail("argument " + actionName(act) + ": not allowed with argument " +
               actionName(other));
        }
      }
    }
    store(act, values);
  }

  double number(Act act, const std::string& text) {
    double v = 0;
    if (!pyFloat(text, &v)) {
      fail("argument " + actionName(act) + ": invalid float value: " + pyRepr(text));
    }
    return v;
  }

  void store(Act act, const std::vector<std::string>& v) {
    switch (act) {
      case Act::Help: throw HelpRequested();
      case Act::Urdf: args_.urdf = true; break;
      case Act::Sdf: args_.sdf = true; break;
      case Act::File: args_.file = v[0]; args_.has_file = true; break;
      case Act::Param: args_.param = v[0]; args_.has_param = true; break;
      case Act::Database: args_.database = v[0]; args_.has_database = true; break;
      case Act::Stdin: args_.from_stdin = true; break;
      case Act::Model: args_.model = v[0]; break;
      case Act::ReferenceFrame: args_.reference_frame = v[0]; break;
      case Act::GazeboNamespace: args_.gazebo_namespace = v[0]; break;
      case Act::RobotNamespace:
        args_.robot_namespace = v[0];
        args_.has_robot_namespace = true;
        break;
      case Act::Unpause: args_.unpause = true; break;
      case Act::Wait: args_.wait = v[0]; break;
      case Act::X: args_.x = number(act, v[0]); break;
      case Act::Y: args_.y = number(act, v[0]); break;
      case Act::Z: args_.z = number(act, v[0]); break;
      case Act::Roll: args_.R = number(act, v[0]); break;
      case Act::Pitch: args_.P = number(act, v[0]); break;
      case Act::Yaw: args_.Y = number(act, v[0]); break;
      case Act::Joint: joint_words_.emplace_back(v[0], v[1]); break;
      case Act::PackageToModel: args_.package_to_model = true; break;
      case Act::Bond: args_.bond = true; break;
      case Act::Unknown: break;
    }
  }

  void checkRequired() {
    if (!seen_.count(Act::Model)) fail("the following arguments are required: -model");
    for (const std::vector<Act>* group : {&kFormatGroup, &kSourceGroup}) {
      bool any = false;
      std::string names;
      for (Act act : *group) {
        any = any || seen_.count(act);
        names += (names.empty() ? "" : " ") + actionName(act);
      }
      if (!any) fail("one of the arguments " + names + " is required");
    }
  }

 public:
  /// -J's words, checked after argparse's own checks (as the Python spawn_model did).
  std::vector<std::pair<std::string, std::string>> joint_words_;

 private:
  std::vector<std::string> words_;
  std::vector<Word> kinds_;
  std::set<size_t> dashes_;
  std::vector<std::string> extras_;
  std::set<Act> seen_;
  SpawnArgs args_;
};

void checkFinite(const SpawnArgs& args) {
  const std::pair<const char*, double> values[] = {
      {"x", args.x}, {"y", args.y}, {"z", args.z}, {"R", args.R}, {"P", args.P}, {"Y", args.Y}};
  for (const auto& v : values) {
    if (!std::isfinite(v.second)) {
      throw UsageError(std::string("spawn_model: error: -") + v.first + " " +
                       pyNonFinite(v.second) + " is not a finite number");
    }
  }
}

std::vector<std::pair<std::string, double>> jointPositions(
    const std::vector<std::pair<std::string, std::string>>& words) {
  std::vector<std::pair<std::string, double>> joints;
  for (const auto& w : words) {
    double position = 0;
    if (!pyFloat(w.second, &position)) {
      throw UsageError("spawn_model: error: -J " + w.first + " " + w.second +
                       ": the position is not a number");
    }
    if (!std::isfinite(position)) {
      throw UsageError("spawn_model: error: -J " + w.first + " " + w.second + " is not finite");
    }
    joints.emplace_back(w.first, position);
  }
  return joints;
}

}  // namespace

SpawnArgs parseSpawnArgs(const std::vector<std::string>& argv) {
  Parser parser(argv);
  SpawnArgs args = parser.parse();
  checkFinite(args);
  args.joints = jointPositions(parser.joint_words_);
  if (args.has_database) {
    throw UsageError("spawn_model: error: -database " + args.database +
                     ": Gazebo's online model database cannot be reached here; use -file or "
                     "-param");
  }
  return args;
}

const std::string& usage() {
  static const std::string text(kUsage);
  return text;
}

const std::string& help() {
  static const std::string text = std::string(kUsage) + kOptions;
  return text;
}

}  // namespace gazebo_ros_spawn
