// Documents, worlds, lights and plugins field by field.
#include <map>

#include "dom_compare.h"
#include "plugin_params.h"

namespace bullet_sim_test {

using namespace bullet_sim;

namespace {

void compareWorlds(DomComparer* cmp, const SdfWorld& ours, const SdfWorld& theirs,
                   const CanonicalLinks& canonical) {
  cmp->text("name", ours.name, theirs.name);
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->vector("gravity", ours.gravity, theirs.gravity);
  cmp->number("max_step_size_s", ours.max_step_size_s, theirs.max_step_size_s);
  cmp->number("real_time_update_rate_hz", ours.real_time_update_rate_hz,
              theirs.real_time_update_rate_hz);
  cmp->number("real_time_factor", ours.real_time_factor, theirs.real_time_factor);
  cmp->colour("ambient", ours.ambient, theirs.ambient);
  cmp->colour("background", ours.background, theirs.background);
  cmp->byName("lights", ours.lights, theirs.lights,
              [cmp](const SdfLight& a, const SdfLight& b, const std::string&) {
                compareLights(cmp, a, b);
              });
  cmp->byName("models", ours.models, theirs.models,
              [cmp, &canonical](const SdfModel& a, const SdfModel& b, const std::string& key) {
                compareModels(cmp, a, b, modelFieldPath("world", key), canonical);
              });
  comparePlugins(cmp, "plugins", ours.plugins, theirs.plugins);
}

/// Parameters keyed by path (a repeated path as `path#2`).
std::map<std::string, std::string> keyedParameters(const std::vector<PluginParameter>& list) {
  std::map<std::string, std::string> out;
  std::map<std::string, int> seen;
  for (const auto& [path, text] : list) {
    const int n = ++seen[path];
    out[n == 1 ? path : path + "#" + std::to_string(n)] = text;
  }
  return out;
}

void compareParameters(DomComparer* cmp, const SdfPlugin& ours, const SdfPlugin& theirs) {
  std::string problem_ours, problem_theirs;
  const auto mine = keyedParameters(pluginParameters(ours.xml, &problem_ours));
  const auto other = keyedParameters(pluginParameters(theirs.xml, &problem_theirs));
  cmp->text("xml", problem_ours, problem_theirs);
  for (const auto& [path, text] : mine) {
    const auto match = other.find(path);
    cmp->text("parameters[" + path + "]", text,
              match == other.end() ? "(absent)" : match->second);
  }
  for (const auto& [path, text] : other) {
    if (!mine.count(path)) cmp->text("parameters[" + path + "]", "(absent)", text);
  }
}

}  // namespace

void compareLights(DomComparer* cmp, const SdfLight& ours, const SdfLight& theirs) {
  cmp->text("name", ours.name, theirs.name);
  cmp->text("type", ours.type, theirs.type);
  cmp->origin("origin", ours.origin, theirs.origin);
  cmp->pose("T_world_light", ours.T_world_light, theirs.T_world_light);
  cmp->colour("diffuse", ours.diffuse, theirs.diffuse);
  cmp->colour("specular", ours.specular, theirs.specular);
  cmp->number("range_m", ours.range_m, theirs.range_m);
  cmp->number("constant", ours.constant, theirs.constant);
  cmp->number("linear", ours.linear, theirs.linear);
  cmp->number("quadratic", ours.quadratic, theirs.quadratic);
  // sdf::Light reads <direction> for spot and directional lights only and <spot> for spot
  // lights only (elsewhere it says the class defaults): on other lights they mean nothing
  // and libsdformat has no reading of them to compare.
  if (theirs.type == "spot" || theirs.type == "directional") {
    cmp->vector("direction", ours.direction, theirs.direction);
  }
  if (theirs.type == "spot") {
    cmp->number("spot_inner_rad", ours.spot_inner_rad, theirs.spot_inner_rad);
    cmp->number("spot_outer_rad", ours.spot_outer_rad, theirs.spot_outer_rad);
    cmp->number("spot_falloff", ours.spot_falloff, theirs.spot_falloff);
  }
  cmp->flag("cast_shadows", ours.cast_shadows, theirs.cast_shadows);
}

void comparePlugins(DomComparer* cmp, const std::string& field,
                    const std::vector<SdfPlugin>& ours, const std::vector<SdfPlugin>& theirs) {
  cmp->byName(field, ours, theirs, [cmp](const SdfPlugin& a, const SdfPlugin& b,
                                         const std::string&) {
    cmp->text("name", a.name, b.name);
    cmp->text("filename", a.filename, b.filename);
    compareParameters(cmp, a, b);
  });
}

void compareDocuments(DomComparer* cmp, const SdfDocument& ours, const SdfDocument& theirs,
                      const CanonicalLinks& canonical) {
  cmp->text("version", ours.version, theirs.version);
  cmp->optional("world", ours.world, theirs.world,
                [&](const SdfWorld& a, const SdfWorld& b) {
                  compareWorlds(cmp, a, b, canonical);
                });
  cmp->optional("model", ours.model, theirs.model,
                [&](const SdfModel& a, const SdfModel& b) {
                  compareModels(cmp, a, b, "model", canonical);
                });
  cmp->optional("light", ours.light, theirs.light,
                [&](const SdfLight& a, const SdfLight& b) { compareLights(cmp, a, b); });
}

}  // namespace bullet_sim_test
