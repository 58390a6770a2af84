// libFuzzer target: a mesh file of arbitrary bytes read with assimp and flattened as the
// loaders read meshes, in this process (importMeshFile: readMeshFile's child process
// would hide the coverage from libFuzzer, and assimp's crashes with it). The first byte
// picks the file name's extension, which is what assimp chooses its importer by ('0' STL,
// '1' OBJ, '2' COLLADA: the seeds start so). A LoadError is the expected answer to bad
// input; anything else stops the run (bench/fuzz runs this target in fork mode, going on
// after assimp's crashes and counting them).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "bullet_sim/errors.h"
#include "bullet_sim/description/mesh.h"
#include "description/mesh/mesh_import.h"

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
    importMeshFile(path);
  } catch (const LoadError& e) {
    // FUZZ_VERBOSE=1 shows why an input was refused (to check seeds and minimised inputs).
    if (std::getenv("FUZZ_VERBOSE")) std::fprintf(stderr, "LoadError: %s\n", e.what());
  }
  unlink(path.c_str());
  return 0;
}
