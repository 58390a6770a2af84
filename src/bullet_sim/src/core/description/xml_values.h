#ifndef BULLET_SIM_CORE_XML_VALUES_H
#define BULLET_SIM_CORE_XML_VALUES_H

#include <string>

#include <tinyxml2.h>

#include "bullet_sim/types.h"

namespace bullet_sim {

/// `s` without leading and trailing white space.
std::string trimmed(const std::string& s);
/// The number `s` spells in full (strtod's syntax, "nan" and "inf" included); false for
/// anything else.
bool parseNumber(const std::string& s, double* out);

/// Reads typed values from tinyxml2 elements. A malformed value throws
/// LoadError naming the source, the element path given as `where` and the text.
class XmlValues {
 public:
  explicit XmlValues(std::string source) : source_(std::move(source)) {}

  /// Text of child `name` of `parent`, trimmed; `fallback` if the child is absent.
  std::string text(const tinyxml2::XMLElement* parent, const char* name,
                   const std::string& fallback) const;
  double number(const tinyxml2::XMLElement* parent, const char* name, double fallback,
                const std::string& where) const;
  bool boolean(const tinyxml2::XMLElement* parent, const char* name, bool fallback,
               const std::string& where) const;
  /// "x y z roll pitch yaw" as in SDF <pose>.
  Pose3 pose(const tinyxml2::XMLElement* parent, const char* name,
             const std::string& where) const;
  [[noreturn]] void fail(const std::string& where, const std::string& what) const;

  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_XML_VALUES_H
