#include "bullet_sim/description/mesh.h"

#include <filesystem>
#include <map>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <Eigen/Geometry>

#include "bullet_sim/errors.h"
#include "description/mesh/mesh_import.h"

namespace bullet_sim {
namespace {

namespace fs = std::filesystem;

Eigen::Matrix4d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2,
      m.d3, m.d4;
  return out;
}

/// The file's own diffuse colour of a material; none for assimp's stand-in material
/// (STL, OBJ without MTL), which is not the file's.
std::optional<Eigen::Vector4f> diffuseOf(const aiMaterial& material) {
  aiString name;
  if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
      std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME) {
    return std::nullopt;
  }
  aiColor4D c;
  if (material.Get(AI_MATKEY_COLOR_DIFFUSE, c) != AI_SUCCESS) return std::nullopt;
  return Eigen::Vector4f(c.r, c.g, c.b, c.a);
}

/// The file of a material's diffuse texture as Gazebo Classic finds it: the name as
/// written (absolute or relative to the mesh's folder), then its file name in the mesh's
/// folder and in ../materials/textures beside it. Sets `missing` when none exists.
std::string textureOf(const aiMaterial& material, const fs::path& mesh_dir, std::string* missing) {
  aiString name;
  if (material.GetTexture(aiTextureType_DIFFUSE, 0, &name) != AI_SUCCESS) return "";
  std::string written = name.C_Str();
  if (written.rfind("file://", 0) == 0) written = written.substr(7);
  if (written.empty() || written[0] == '*') return "";  // none, or embedded: not read
  const fs::path file = fs::path(written).filename();
  for (const fs::path& candidate :
       {fs::path(written).is_absolute() ? fs::path(written) : mesh_dir / written, mesh_dir / file,
        mesh_dir / ".." / "materials" / "textures" / file}) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return fs::weakly_canonical(candidate, ec).string();
  }
  *missing = written;
  return "";
}

/// Collects the triangles of every node, transformed into the file's root frame, one
/// part per material.
class SceneFlattener {
 public:
  SceneFlattener(const aiScene& scene, const fs::path& dir) : scene_(scene), dir_(dir) {}

  std::vector<MeshPart> flatten() {
    visit(*scene_.mRootNode, Eigen::Matrix4d::Identity());
    std::vector<MeshPart> parts;
    for (auto& [material, part] : parts_) {
      if (!part.triangles.empty()) parts.push_back(std::move(part));
    }
    return parts;
  }

 private:
  void visit(const aiNode& node, const Eigen::Matrix4d& T_parent) {
    const Eigen::Matrix4d T = T_parent * toEigen(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) add(*scene_.mMeshes[node.mMeshes[i]], T);
    for (unsigned i = 0; i < node.mNumChildren; ++i) visit(*node.mChildren[i], T);
  }

  void add(const aiMesh& mesh, const Eigen::Matrix4d& T) {
    auto [it, inserted] = parts_.try_emplace(mesh.mMaterialIndex);
    MeshPart& part = it->second;
    if (inserted && mesh.mMaterialIndex < scene_.mNumMaterials) {
      const aiMaterial& material = *scene_.mMaterials[mesh.mMaterialIndex];
      part.rgba = diffuseOf(material);
      part.texture_path = textureOf(material, dir_, &part.missing_texture);
    }
    // Coordinates for a textured part only, one per vertex (0 0 where a mesh of the part
    // has none); v counted from the image's top row.
    const bool textured = !part.texture_path.empty();
    const bool has_uvs = mesh.HasTextureCoords(0);
    const auto base = static_cast<uint32_t>(part.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      part.vertices.push_back((T * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>());
      if (textured) {
        part.uvs.push_back(has_uvs ? Eigen::Vector2f(mesh.mTextureCoords[0][v].x,
                                                     1.0f - mesh.mTextureCoords[0][v].y)
                                   : Eigen::Vector2f::Zero());
      }
    }
    // A mirroring transform turns the winding around; keep faces pointing outwards.
    const bool mirrored = T.topLeftCorner<3, 3>().determinant() < 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      std::array<uint32_t, 3> tri{};
      for (int c = 0; c < 3; ++c) tri[c] = base + face.mIndices[c];
      if (!validTriangle(part, tri)) continue;
      if (mirrored) std::swap(tri[1], tri[2]);
      part.triangles.push_back(tri);
    }
  }

  /// Indices within the part and a non-zero area: assimp passes on what a damaged file
  /// says (a COLLADA <p> naming missing vertices gives triangles on one point).
  static bool validTriangle(const MeshPart& part, const std::array<uint32_t, 3>& tri) {
    for (uint32_t index : tri)
      if (index >= part.vertices.size()) return false;
    const Eigen::Vector3d& a = part.vertices[tri[0]];
    return (part.vertices[tri[1]] - a).cross(part.vertices[tri[2]] - a).squaredNorm() > 0;
  }

  const aiScene& scene_;
  const fs::path dir_;
  std::map<unsigned, MeshPart> parts_;  ///< by material index
};

int64_t modifiedTime(const fs::path& path) {
  std::error_code ec;
  return static_cast<int64_t>(fs::last_write_time(path, ec).time_since_epoch().count());
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out.empty() ? "nowhere" : out;
}

/// True when a material of the scene has a diffuse texture: only then are the texture
/// coordinates kept.
bool hasDiffuseTexture(const aiScene& scene) {
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    if (scene.mMaterials[i]->GetTextureCount(aiTextureType_DIFFUSE) > 0) return true;
  }
  return false;
}

}  // namespace

size_t TriangleMesh::triangleCount() const {
  size_t n = 0;
  for (const MeshPart& p : parts) n += p.triangles.size();
  return n;
}

size_t TriangleMesh::vertexCount() const {
  size_t n = 0;
  for (const MeshPart& p : parts) n += p.vertices.size();
  return n;
}

TriangleMesh importMeshFile(const std::string& path) {
  Assimp::Importer importer;
  // Gazebo Classic reads COLLADA with its own loader, which applies <unit> and ignores
  // <up_axis> (gazebo-classic issue 1305): vertices are taken as written, Z up. assimp
  // applies <unit> too, and with this flag leaves the axes alone.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(path, 0);
  if (!scene || !scene->mRootNode) {
    throw LoadError(path + ": cannot read mesh: " + importer.GetErrorString());
  }
  // Positions, materials and, for a textured file, texture coordinates are used: without
  // the rest the corners that faces share become one vertex (smaller hulls, less to
  // transform), unless their texture coordinates differ.
  int dropped = aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
                aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS | aiComponent_TEXTURES |
                aiComponent_LIGHTS | aiComponent_CAMERAS;
  if (!hasDiffuseTexture(*scene)) dropped |= aiComponent_TEXCOORDS;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, dropped);
  scene = importer.ApplyPostProcessing(aiProcess_RemoveComponent | aiProcess_Triangulate |
                                       aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) {
    throw LoadError(path + ": cannot read mesh: " + importer.GetErrorString());
  }
  TriangleMesh mesh;
  mesh.path = path;
  mesh.parts = SceneFlattener(*scene, fs::path(path).parent_path()).flatten();
  if (mesh.parts.empty()) throw LoadError(path + ": mesh has no triangles");
  return mesh;
}

std::shared_ptr<const TriangleMesh> MeshCache::load(const std::string& path) {
  std::error_code ec;
  const uintmax_t size = fs::file_size(path, ec);
  const int64_t modified = modifiedTime(path);
  std::lock_guard<std::mutex> lock(mutex_);
  Entry& entry = entries_[path];
  if (auto mesh = entry.mesh.lock()) {
    if (entry.modified == modified && entry.size == size) return mesh;
  }
  ++file_reads_;
  auto mesh = std::make_shared<const TriangleMesh>(readMeshFile(path));
  entry.mesh = mesh;
  entry.modified = modified;
  entry.size = size;
  return mesh;
}

size_t MeshCache::fileReads() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return file_reads_;
}

MeshCache& MeshCache::shared() {
  static MeshCache cache;
  return cache;
}

std::shared_ptr<const TriangleMesh> loadMeshUri(const UriResolver& resolver,
                                                const std::string& uri,
                                                const std::string& base_dir,
                                                std::string* reason) {
  std::vector<std::string> searched;
  const std::string path = resolver.resolve(uri, base_dir, &searched);
  if (path.empty()) {
    *reason = "file not found (searched " + joined(searched) + ")";
    return nullptr;
  }
  try {
    return MeshCache::shared().load(path);
  } catch (const LoadError& e) {
    *reason = e.what();
    return nullptr;
  }
}

}  // namespace bullet_sim
