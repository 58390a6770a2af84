#ifndef BULLET_SIM_CORE_SDF_VALUES_H
#define BULLET_SIM_CORE_SDF_VALUES_H

#include <string>

#include <Eigen/Geometry>
#include <tinyxml2.h>

#include "description/sdf/sdf_dom.h"

namespace bullet_sim {

/// An SDF <sdf version="major.minor">.
struct SdfVersion {
  int major = 1, minor = 9;
  bool before(int maj, int min) const { return major < maj || (major == maj && minor < min); }
};

/// A <pose> as written: the transform and the frame it is relative to ("" = the default).
struct RawPose {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  std::string relative_to;
};

/// Typed values of the elements of one SDF file. A malformed value throws LoadError
/// "FILE:LINE: <parent> <element>: 'text' is not ..." naming the file, line and element.
class SdfValues {
 public:
  SdfValues(std::string file, SdfVersion version)
      : file_(std::move(file)), version_(version) {}

  const std::string& file() const { return file_; }
  SdfVersion version() const { return version_; }
  SdfOrigin origin(const tinyxml2::XMLElement* e) const { return {file_, e->GetLineNum()}; }

  /// Trimmed text of `e` ("" when it has none).
  static std::string text(const tinyxml2::XMLElement* e);
  /// Text of child `name`, or `fallback` when there is no such child.
  std::string text(const tinyxml2::XMLElement* parent, const char* name,
                   const std::string& fallback) const;
  /// Attribute `name` of `e`, or `fallback`.
  static std::string attribute(const tinyxml2::XMLElement* e, const char* name,
                               const std::string& fallback = "");
  /// A required attribute. @throws LoadError naming the element when it is missing.
  std::string requiredAttribute(const tinyxml2::XMLElement* e, const char* name) const;

  double number(const tinyxml2::XMLElement* parent, const char* name, double fallback) const;
  bool boolean(const tinyxml2::XMLElement* parent, const char* name, bool fallback) const;
  Eigen::Vector3d vector3(const tinyxml2::XMLElement* parent, const char* name,
                          const Eigen::Vector3d& fallback) const;
  Eigen::Vector2d vector2(const tinyxml2::XMLElement* parent, const char* name,
                          const Eigen::Vector2d& fallback) const;
  /// "r g b a" (a may be left out, as libsdformat allows).
  Eigen::Vector4f color(const tinyxml2::XMLElement* parent, const char* name,
                        const Eigen::Vector4f& fallback) const;
  /// The <pose> child of `parent` (identity when absent): "x y z roll pitch yaw" or, from
  /// SDF 1.9, as its rotation_format and degrees attributes say. Its frame: relative_to
  /// (1.7+), or the `frame` attribute of 1.5/1.6, which libsdformat renames to relative_to.
  RawPose pose(const tinyxml2::XMLElement* parent) const;

  /// "FILE:LINE: <a> <b>" for element `e`, with its name attribute where it has one.
  std::string where(const tinyxml2::XMLElement* e) const;
  [[noreturn]] void fail(const tinyxml2::XMLElement* e, const std::string& what) const;

 private:
  std::vector<double> numbers(const tinyxml2::XMLElement* e, size_t min_count,
                              size_t max_count, const std::string& expected) const;

  std::string file_;
  SdfVersion version_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_VALUES_H
