#include "plugin_params.h"

#include <tinyxml2.h>

namespace bullet_sim_test {

namespace {

std::string trimmed(const char* text) {
  const std::string s = text ? text : "";
  const size_t first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

void collect(const tinyxml2::XMLElement& element, const std::string& path,
             std::vector<PluginParameter>* out) {
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    out->emplace_back(path + "@" + a->Name(), trimmed(a->Value()));
  }
  if (!element.FirstChildElement()) {
    out->emplace_back(path, trimmed(element.GetText()));
    return;
  }
  for (const tinyxml2::XMLElement* c = element.FirstChildElement(); c;
       c = c->NextSiblingElement()) {
    collect(*c, path + "/" + c->Name(), out);
  }
}

}  // namespace

std::vector<PluginParameter> pluginParameters(const std::string& xml, std::string* problem) {
  std::vector<PluginParameter> out;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS || !doc.RootElement()) {
    *problem = std::string("not XML: ") + doc.ErrorStr();
    return out;
  }
  for (const tinyxml2::XMLElement* c = doc.RootElement()->FirstChildElement(); c;
       c = c->NextSiblingElement()) {
    collect(*c, c->Name(), &out);
  }
  return out;
}

}  // namespace bullet_sim_test
