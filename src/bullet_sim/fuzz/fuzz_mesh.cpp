// libFuzzer target: a mesh file of arbitrary bytes read as the loaders read meshes
// (readMeshFile, assimp). The first byte picks the file name's extension, which is what
// assimp chooses its importer by ('0' STL, '1' OBJ, '2' COLLADA: the seeds start so).
// A LoadError is the expected answer to bad input; anything else stops the run.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "bullet_sim/errors.h"
#include "bullet_sim/mesh.h"

using namespace bullet_sim;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".stl", ".obj", ".dae"};
  // One file per process (and extension) in the current folder, which bench/fuzz makes a
  // scratch folder: an OBJ's mtllib is looked up beside it.
  const std::string path = "fuzz_mesh_" + std::to_string(getpid()) + kExtensions[data[0] % 3];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    readMeshFile(path);
  } catch (const LoadError& e) {
    // FUZZ_VERBOSE=1 shows why an input was refused (to check seeds and minimised inputs).
    if (std::getenv("FUZZ_VERBOSE")) std::fprintf(stderr, "LoadError: %s\n", e.what());
  }
  unlink(path.c_str());
  return 0;
}
