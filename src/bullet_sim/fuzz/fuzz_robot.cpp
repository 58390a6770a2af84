// libFuzzer target: a robot description as the node reads it from robot_description
// (urdfdom plus the Gazebo extension tags and meshes), then planned and spawned into an
// empty world and stepped, so that the planner's paths see what the parser lets through.
// A LoadError is the expected answer to bad input; anything else stops the run.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <string>

#include "bullet_sim/errors.h"
#include "bullet_sim/description/resource_paths.h"
#include "bullet_sim/description/robot_spec.h"
#include "bullet_sim/simulation.h"
#include "bullet_sim/description/world_spec.h"

using namespace bullet_sim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // No model or package folders: a run must not depend on what the machine has installed.
  static const UriResolver resolver{ResourcePaths{}};
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const RobotSpec spec = parseRobot(text, "robot_description", resolver);
    Simulation sim(WorldSpec{}, SimConfig{});
    sim.spawnRobot("fuzzed", spec, Pose3{});
    sim.step();
    sim.step();
  } catch (const LoadError& e) {
    // FUZZ_VERBOSE=1 shows why an input was refused (to check seeds and minimised inputs).
    if (std::getenv("FUZZ_VERBOSE")) std::fprintf(stderr, "LoadError: %s\n", e.what());
  }
  return 0;
}
