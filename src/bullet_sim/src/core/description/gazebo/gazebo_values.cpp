#include "description/gazebo/gazebo_values.h"

#include <cmath>

namespace bullet_sim {

std::string attribute(const tinyxml2::XMLElement* e, const char* name) {
  const char* v = e->Attribute(name);
  return v ? v : "";
}

double readRate(const XmlValues& xml, const tinyxml2::XMLElement* parent, const char* name,
                double fallback, const std::string& where) {
  const double hz = xml.number(parent, name, fallback, where);
  if (!(hz >= 0 && std::isfinite(hz))) {
    xml.fail(where + " <" + name + ">", "'" + xml.text(parent, name, "") +
                                            "' is not a rate >= 0 Hz");
  }
  return hz;
}

}  // namespace bullet_sim
