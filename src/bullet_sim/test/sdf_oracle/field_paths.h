#ifndef BULLET_SIM_TEST_FIELD_PATHS_H
#define BULLET_SIM_TEST_FIELD_PATHS_H

#include <string>

namespace bullet_sim_test {

/// The field path of model `name` inside the world or model at `parent` ("world",
/// "model", "world.models[a]"): `parent` + ".models[" + name + "]". A document that is a
/// model has the path "model". The comparer's messages and the oracle's canonical links
/// use these paths.
inline std::string modelFieldPath(const std::string& parent, const std::string& name) {
  return parent + ".models[" + name + "]";
}

}  // namespace bullet_sim_test

#endif  // BULLET_SIM_TEST_FIELD_PATHS_H
