#ifndef BULLET_SIM_CORE_MESH_IMPORT_H
#define BULLET_SIM_CORE_MESH_IMPORT_H

#include <string>

#include "bullet_sim/description/mesh.h"

namespace bullet_sim {

/// Reads a mesh file with assimp in this process (readMeshFile runs it in a child process).
/// Exposed for the mesh fuzzer, which needs assimp's and the flattening's coverage.
/// @throws LoadError as readMeshFile; a damaged file may also crash assimp.
TriangleMesh importMeshFile(const std::string& path);

}  // namespace bullet_sim

#endif  // BULLET_SIM_CORE_MESH_IMPORT_H
