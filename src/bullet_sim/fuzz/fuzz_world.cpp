// libFuzzer target: an SDF world as text (the SDF reader: versions 1.0 to 1.9, frames and
// relative poses, includes of the built-in models, <state>, materials, movable models),
// then a Simulation built from it and stepped.
// A LoadError is the expected answer to bad input; anything else stops the run.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <string>

#include "bullet_sim/errors.h"
#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/simulation.h"
#include "bullet_sim/description/world_spec.h"

using namespace bullet_sim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // Only the built-in sun and ground_plane: a run must not depend on installed models.
  static const UriResolver resolver{ResourcePaths{}};
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const WorldSpec world = loadWorldString(text, "fuzzed.world", resolver);
    Simulation sim(world, SimConfig{});
    sim.step();
    sim.step();
  } catch (const LoadError& e) {
    // FUZZ_VERBOSE=1 shows why an input was refused (to check seeds and minimised inputs).
    if (std::getenv("FUZZ_VERBOSE")) std::fprintf(stderr, "LoadError: %s\n", e.what());
  }
  return 0;
}
