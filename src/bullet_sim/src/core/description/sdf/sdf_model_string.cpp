#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/errors.h"
#include "description/sdf/sdf_model.h"
#include "description/sdf/sdf_reader.h"

namespace bullet_sim {

RobotSpec parseSdfModelString(const std::string& sdf_xml, const std::string& source_name,
                              const UriResolver& resolver) {
  const auto xml = parseSdfXml(sdf_xml, source_name, "model");
  std::vector<std::string> warnings;
  const SdfDocument doc = readSdf(*xml, source_name, "", resolver, &warnings);
  if (!doc.model) throw LoadError(source_name + ": no <model> element (an SDF model is expected)");
  RobotSpec spec = parseSdfModel(*doc.model, source_name, resolver);
  spec.warnings.insert(spec.warnings.begin(), warnings.begin(), warnings.end());
  return spec;
}

RobotSpec parseSdfModelString(const std::string& sdf_xml, const std::string& source_name) {
  return parseSdfModelString(sdf_xml, source_name, UriResolver(ResourcePaths::fromEnvironment()));
}

}  // namespace bullet_sim
