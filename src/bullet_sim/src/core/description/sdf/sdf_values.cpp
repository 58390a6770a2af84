#include "description/sdf/sdf_values.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "bullet_sim/errors.h"
#include "description/xml_values.h"

namespace bullet_sim {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

Eigen::Matrix3d rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

std::string SdfValues::text(const tinyxml2::XMLElement* e) {
  return trimmed(e && e->GetText() ? e->GetText() : "");
}

std::string SdfValues::text(const tinyxml2::XMLElement* parent, const char* name,
                            const std::string& fallback) const {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
  return e ? text(e) : fallback;
}

std::string SdfValues::attribute(const tinyxml2::XMLElement* e, const char* name,
                                 const std::string& fallback) {
  const char* value = e->Attribute(name);
  return value ? trimmed(value) : fallback;
}

std::string SdfValues::requiredAttribute(const tinyxml2::XMLElement* e, const char* name) const {
  const char* value = e->Attribute(name);
  if (!value) fail(e, std::string("the required attribute '") + name + "' is missing");
  return trimmed(value);
}

std::vector<double> SdfValues::numbers(const tinyxml2::XMLElement* e, size_t min_count,
                                       size_t max_count, const std::string& expected) const {
  const std::string s = text(e);
  std::istringstream in(s);
  std::vector<double> v;
  std::string token;
  bool ok = true;
  while (in >> token) {
    double d = 0;
    ok = ok && parseNumber(token, &d);
    v.push_back(d);
  }
  if (!ok || v.size() < min_count || v.size() > max_count) {
    fail(e, "'" + s + "' is not " + expected);
  }
  return v;
}

double SdfValues::number(const tinyxml2::XMLElement* parent, const char* name,
                         double fallback) const {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
  return e ? numbers(e, 1, 1, "a number")[0] : fallback;
}

bool SdfValues::boolean(const tinyxml2::XMLElement* parent, const char* name,
                        bool fallback) const {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
  if (!e) return fallback;
  const std::string s = lower(text(e));
  if (s == "true" || s == "1") return true;
  if (s == "false" || s == "0") return false;
  fail(e, "'" + text(e) + "' is not a boolean (true, false, 1 or 0)");
}

Eigen::Vector3d SdfValues::vector3(const tinyxml2::XMLElement* parent, const char* name,
                                   const Eigen::Vector3d& fallback) const {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
  if (!e) return fallback;
  const std::vector<double> v = numbers(e, 3, 3, "three numbers 'x y z'");
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Vector2d SdfValues::vector2(const tinyxml2::XMLElement* parent, const char* name,
                                   const Eigen::Vector2d& fallback) const {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
  if (!e) return fallback;
  const std::vector<double> v = numbers(e, 2, 2, "two numbers 'x y'");
  return Eigen::Vector2d(v[0], v[1]);
}

Eigen::Vector4f SdfValues::color(const tinyxml2::XMLElement* parent, const char* name,
                                 const Eigen::Vector4f& fallback) const {
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(name) : nullptr;
  if (!e) return fallback;
  const std::vector<double> v = numbers(e, 3, 4, "a colour 'r g b a'");
  return Eigen::Vector4f(static_cast<float>(v[0]), static_cast<float>(v[1]),
                         static_cast<float>(v[2]), v.size() == 4 ? static_cast<float>(v[3]) : 1.0f);
}

RawPose SdfValues::pose(const tinyxml2::XMLElement* parent) const {
  RawPose out;
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement("pose") : nullptr;
  if (!e) return out;
  out.relative_to = attribute(e, "relative_to");
  if (version_.before(1, 7) && out.relative_to.empty()) out.relative_to = attribute(e, "frame");
  const std::string format = version_.before(1, 9) ? "euler_rpy"
                                                   : attribute(e, "rotation_format", "euler_rpy");
  const bool degrees = !version_.before(1, 9) && lower(attribute(e, "degrees")) == "true";
  if (text(e).empty()) return out;
  if (format == "quat_xyzw") {
    const std::vector<double> v = numbers(e, 7, 7, "'x y z qx qy qz qw'");
    out.T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
    out.T.linear() = Eigen::Quaterniond(v[6], v[3], v[4], v[5]).normalized().toRotationMatrix();
    return out;
  }
  if (format != "euler_rpy") fail(e, "rotation_format '" + format + "' is not euler_rpy or quat_xyzw");
  std::vector<double> v = numbers(e, 6, 6, "'x y z roll pitch yaw'");
  if (degrees) {
    for (int i = 3; i < 6; ++i) v[i] *= M_PI / 180.0;
  }
  out.T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  out.T.linear() = rpy(v[3], v[4], v[5]);
  return out;
}

std::string SdfValues::where(const tinyxml2::XMLElement* e) const {
  std::string path;
  for (const tinyxml2::XMLElement* p = e; p && std::string(p->Name()) != "sdf";
       p = p->Parent() ? p->Parent()->ToElement() : nullptr) {
    const char* name = p->Attribute("name");
    const std::string tag = std::string("<") + p->Name() +
                            (name ? std::string(" name=\"") + name + "\"" : "") + ">";
    path = path.empty() ? tag : tag + " " + path;
  }
  return file_ + ":" + std::to_string(e->GetLineNum()) + ": " + path;
}

void SdfValues::fail(const tinyxml2::XMLElement* e, const std::string& what) const {
  throw LoadError(where(e) + ": " + what);
}

}  // namespace bullet_sim
