#ifndef BULLET_SIM_MESH_H
#define BULLET_SIM_MESH_H

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "bullet_sim/description/resource_paths.h"

namespace bullet_sim {

/// The triangles of one material of a mesh file.
struct MeshPart {
  std::vector<Eigen::Vector3d> vertices;                ///< metres, Z up
  std::vector<std::array<uint32_t, 3>> triangles;       ///< counter-clockwise seen from outside
  /// Diffuse colour of the part's material in the file (COLLADA, OBJ/MTL); none when the
  /// file gives none (STL), and the visual's own colour is used instead.
  std::optional<Eigen::Vector4f> rgba;
  /// Texture coordinates, one per vertex (u from the left, v from the top row of the
  /// image), when the part's material has a diffuse texture; otherwise empty.
  std::vector<Eigen::Vector2f> uvs;
  /// The diffuse texture's file, found as Gazebo does (beside the mesh, then in
  /// ../materials/textures); empty when the material has none or it was not found.
  std::string texture_path;
  /// The texture's name as the file gives it when it was not found (for the warning).
  std::string missing_texture;
};

/// A mesh file as Gazebo shows it: every node transform applied, COLLADA's <unit> applied
/// and its <up_axis> ignored as Gazebo Classic does (vertices as written, Z up, in metres),
/// triangles only (points and lines dropped). A material's diffuse texture comes with the
/// part's texture coordinates.
struct TriangleMesh {
  std::string path;  ///< the file it was read from
  std::vector<MeshPart> parts;

  size_t triangleCount() const;
  size_t vertexCount() const;
};

/// Reads mesh files with assimp (STL ASCII and binary, COLLADA, OBJ, and whatever else
/// assimp reads) and keeps each one while anything uses it: a file is read once however
/// many links, robots or world models name it, and read again when it changed on disk.
/// Thread-safe.
class MeshCache {
 public:
  /// The mesh in the file at `path` (an existing file's path, after URI resolution).
  /// @throws LoadError "<path>: cannot read mesh: <assimp's reason>" when assimp cannot read
  /// it, or "<path>: mesh has no triangles" when it holds none.
  std::shared_ptr<const TriangleMesh> load(const std::string& path);

  /// How many times a file was actually read (for tests of the sharing).
  size_t fileReads() const;

  /// The cache every loader of the process uses.
  static MeshCache& shared();

 private:
  struct Entry {
    std::weak_ptr<const TriangleMesh> mesh;
    int64_t modified = 0;  ///< file time when read
    uintmax_t size = 0;    ///< file size when read
  };
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
  size_t file_reads_ = 0;
};

/// Reads one mesh file without any cache, with assimp in a child process: assimp crashes on
/// some damaged files, and that must not end the simulator.
/// @throws LoadError as MeshCache::load, "<path>: cannot read mesh: assimp crashed
/// reading it (<signal>)", or "... assimp did not finish reading it in 60 s" (the child is
/// killed).
TriangleMesh readMeshFile(const std::string& path);

/// Resolves `uri` (relative ones from `base_dir`) and loads it through MeshCache::shared().
/// Returns null and sets `reason` ("file not found (searched ...)" or the LoadError text
/// naming the path and assimp's reason) when that fails.
std::shared_ptr<const TriangleMesh> loadMeshUri(const UriResolver& resolver,
                                                const std::string& uri,
                                                const std::string& base_dir,
                                                std::string* reason);

}  // namespace bullet_sim

#endif  // BULLET_SIM_MESH_H
