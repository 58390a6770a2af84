#include "model_text.h"

#include <tinyxml2.h>

#include <cctype>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace gazebo_ros_spawn {

std::string readModelFile(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) {
    throw ModelError("specified file " + path + " does not exist");
  }
  if (!S_ISREG(info.st_mode)) throw ModelError("specified file " + path + " is not a file");
  std::ifstream in(path);
  if (!in) throw ModelError("specified file " + path + " cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void checkXml(const std::string& text, const std::string& source) {
  bool blank = true;
  for (unsigned char c : text) blank = blank && std::isspace(c);
  if (blank) throw ModelError(source + " is empty");
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    throw ModelError(source + " is not valid XML: " + doc.ErrorStr());
  }
}

std::string packageToModel(const std::string& text) {
  static const std::string from = "package://", to = "model://";
  std::string out;
  size_t start = 0;
  for (size_t at; (at = text.find(from, start)) != std::string::npos; start = at + from.size()) {
    out.append(text, start, at - start).append(to);
  }
  return out.append(text, start, std::string::npos);
}

}  // namespace gazebo_ros_spawn
