#include "description/sdf/world_state.h"

#include "description/xml_values.h"

namespace bullet_sim {
namespace {

std::string nameOf(const tinyxml2::XMLElement* e) {
  const char* name = e->Attribute("name");
  return name ? name : "";
}

ModelState readModel(const tinyxml2::XMLElement* model, const XmlValues& xml,
                     const std::string& where) {
  ModelState state;
  if (model->FirstChildElement("pose")) state.pose = xml.pose(model, "pose", where);
  for (const tinyxml2::XMLElement* link = model->FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    if (!link->FirstChildElement("pose")) continue;
    const std::string link_where = where + " <link name=\"" + nameOf(link) + "\">";
    state.link_poses[nameOf(link)] = xml.pose(link, "pose", link_where);
  }
  for (const tinyxml2::XMLElement* nested = model->FirstChildElement("model"); nested;
       nested = nested->NextSiblingElement("model")) {
    const std::string nested_where = where + " <model name=\"" + nameOf(nested) + "\">";
    state.models[nameOf(nested)] = readModel(nested, xml, nested_where);
  }
  return state;
}

}  // namespace

WorldState readWorldState(const tinyxml2::XMLElement* world, const std::string& source,
                          std::vector<std::string>* warnings) {
  WorldState state;
  const tinyxml2::XMLElement* saved = world ? world->FirstChildElement("state") : nullptr;
  if (!saved) return state;
  const XmlValues xml(source);
  for (const char* ignored : {"insertions", "deletions"}) {
    if (saved->FirstChildElement(ignored)) {
      warnings->push_back(source + ": <state> <" + ignored + "> is not applied (the models " +
                          "of the world body are loaded as written)");
    }
  }
  for (const tinyxml2::XMLElement* model = saved->FirstChildElement("model"); model;
       model = model->NextSiblingElement("model")) {
    const std::string where = "<state> <model name=\"" + nameOf(model) + "\">";
    state.models[nameOf(model)] = readModel(model, xml, where);
  }
  return state;
}

}  // namespace bullet_sim
