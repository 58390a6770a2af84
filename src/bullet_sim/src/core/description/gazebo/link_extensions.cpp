#include "description/gazebo/link_extensions.h"

#include <cmath>
#include <optional>
#include <utility>

#include "description/material/gazebo_materials.h"

namespace bullet_sim {

using tinyxml2::XMLElement;

void readLinkSurface(const XMLElement* g, const std::string& link, const XmlValues& xml,
                     RobotSpec* spec) {
  const std::string where = "<gazebo reference=\"" + link + "\">";
  if (!g->FirstChildElement("mu1") && !g->FirstChildElement("mu2") &&
      !g->FirstChildElement("kp") && !g->FirstChildElement("kd")) {
    return;
  }
  SurfaceParams s = spec->surfaces[link];
  s.mu1 = xml.number(g, "mu1", s.mu1, where);
  s.mu2 = xml.number(g, "mu2", s.mu2, where);
  s.kp = xml.number(g, "kp", s.kp, where);
  s.kd = xml.number(g, "kd", s.kd, where);
  const std::pair<const char*, double*> coefficients[] = {{"mu1", &s.mu1}, {"mu2", &s.mu2}};
  for (const auto& [name, mu] : coefficients) {
    if (std::isnan(*mu)) {
      xml.fail(where + " <" + name + ">", "'" + xml.text(g, name, "") + "' is not a friction coefficient");
    }
    *mu = frictionCoefficient(*mu);
  }
  spec->surfaces[link] = s;
}

void readLinkMaterial(const XMLElement* g, const std::string& link, const XmlValues& xml,
                      RobotSpec* spec) {
  if (!g->FirstChildElement("material")) return;
  const std::string name = xml.text(g, "material", "");
  std::optional<Eigen::Vector4f> colour = gazeboMaterialColour(name);
  if (!colour) {
    spec->warnings.push_back("<gazebo reference=\"" + link + "\"> <material>: '" + name +
                             "' is not one of Gazebo's stock materials: drawn grey");
    colour = unknownMaterialColour();
  }
  for (VisualSpec& v : spec->visuals) {
    if (v.link == link) v.rgba = *colour;
  }
}

}  // namespace bullet_sim
