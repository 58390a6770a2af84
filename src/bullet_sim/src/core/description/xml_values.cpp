#include "description/xml_values.h"

#include <cstdlib>
#include <sstream>
#include <vector>

#include "bullet_sim/errors.h"

namespace bullet_sim {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

bool parseNumber(const std::string& s, double* out) {
  if (s.empty()) return false;
  char* end = nullptr;
  *out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

std::string XmlValues::text(const tinyxml2::XMLElement* parent, const char* name,
                            const std::string& fallback) const {
  const tinyxml2::XMLElement* e = parent->FirstChildElement(name);
  if (!e) return fallback;
  return trimmed(e->GetText() ? e->GetText() : "");
}

double XmlValues::number(const tinyxml2::XMLElement* parent, const char* name, double fallback,
                         const std::string& where) const {
  if (!parent->FirstChildElement(name)) return fallback;
  const std::string s = text(parent, name, "");
  double value = 0;
  if (!parseNumber(s, &value)) fail(where + " <" + name + ">", "'" + s + "' is not a number");
  return value;
}

bool XmlValues::boolean(const tinyxml2::XMLElement* parent, const char* name, bool fallback,
                        const std::string& where) const {
  if (!parent->FirstChildElement(name)) return fallback;
  const std::string s = text(parent, name, "");
  if (s == "true" || s == "1") return true;
  if (s == "false" || s == "0") return false;
  fail(where + " <" + name + ">", "'" + s + "' is not a boolean (true/false/1/0)");
}

Pose3 XmlValues::pose(const tinyxml2::XMLElement* parent, const char* name,
                      const std::string& where) const {
  Pose3 pose;
  if (!parent->FirstChildElement(name)) return pose;
  const std::string s = text(parent, name, "");
  std::istringstream in(s);
  std::vector<double> v;
  std::string token;
  while (in >> token) {
    double d = 0;
    if (!parseNumber(token, &d)) break;
    v.push_back(d);
  }
  if (v.size() != 6) fail(where + " <" + name + ">", "'" + s + "' is not 'x y z roll pitch yaw'");
  pose.position = Eigen::Vector3d(v[0], v[1], v[2]);
  pose.orientation = Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitX());
  return pose;
}

void XmlValues::fail(const std::string& where, const std::string& what) const {
  throw LoadError(source_ + ": " + where + ": " + what);
}

}  // namespace bullet_sim
