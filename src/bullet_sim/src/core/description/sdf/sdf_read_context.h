#ifndef BULLET_SIM_CORE_SDF_READ_CONTEXT_H
#define BULLET_SIM_CORE_SDF_READ_CONTEXT_H

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "bullet_sim/description/resource_paths.h"
#include "description/sdf/sdf_values.h"

namespace bullet_sim {

/// What one readSdf call shares among the files it reads: the resolver, the warnings, and
/// the documents of included files with their values (alive until the call returns, as the
/// frame scopes point into them).
class SdfReadContext {
 public:
  SdfReadContext(const UriResolver& resolver, std::vector<std::string>* warnings)
      : resolver_(resolver), warnings_(warnings) {}

  /// The root element (<model>, <light>, ...) of the file an <include> names, and the
  /// values of that file.
  struct Included {
    const tinyxml2::XMLElement* root;
    const SdfValues* values;
  };
  /// @throws LoadError naming the <include> (file and line): a URI that names nothing
  /// readable, a file that is not SDF, an include of itself.
  Included include(const tinyxml2::XMLElement* include, const SdfValues& values);

  /// The values of a file, kept alive with the others.
  const SdfValues& valuesOf(const std::string& file, SdfVersion version);

  std::vector<std::string>* warnings() const { return warnings_; }

  /// Leaves an included file once its element is read (for the include-cycle check).
  void leave() { stack_.pop_back(); }

 private:
  const UriResolver& resolver_;
  std::vector<std::string>* warnings_;
  std::deque<std::unique_ptr<tinyxml2::XMLDocument>> documents_;
  std::deque<SdfValues> values_;
  std::vector<std::string> stack_;  ///< files being included, outermost first
};

/// The version of a parsed SDF document's <sdf version> (1.9 when it gives none).
SdfVersion sdfVersionOf(const tinyxml2::XMLDocument& doc);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_SDF_READ_CONTEXT_H
