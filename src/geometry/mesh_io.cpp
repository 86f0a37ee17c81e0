#include "view_direction_classification/geometry/mesh_io.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <system_error>
#include <utility>

#include "view_direction_classification/common/error.h"

// Binary PLY is written from the in-memory representation.
#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "saveMeshPly writes binary_little_endian PLY from memory and needs a little-endian target"
#endif

namespace vdc {
namespace {

namespace fs = std::filesystem;

void checkReadableFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    throw Error("Mesh file '" + path + "' does not exist.");
  }
  if (!fs::is_regular_file(status)) {
    throw Error("Mesh file '" + path + "' is not a regular file.");
  }
  if (fs::file_size(path, ec) == 0 || ec) {
    throw Error("Mesh file '" + path + "' is empty.");
  }
  std::ifstream probe(path, std::ios::binary);
  if (!probe) {
    throw Error("Mesh file '" + path + "' cannot be opened for reading.");
  }
}

// Joins vertices with bit-identical coordinates across all parts of the scene. Assimp's own
// JoinIdenticalVertices works per part and also compares normals, which leaves STL files (one
// normal per face) as a triangle soup.
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh* mesh) : mesh_(mesh) {}

  int index(const aiVector3D& p) {
    const Eigen::Vector3f v(p.x, p.y, p.z);
    std::array<std::uint32_t, 3> key;
    for (int k = 0; k < 3; ++k) {
      // +0.0f folds -0 into 0, so both spellings of zero are one vertex.
      const float coordinate = v[k] + 0.0f;
      std::memcpy(&key[k], &coordinate, sizeof(float));
    }
    const auto found = lookup_.find(key);
    if (found != lookup_.end()) return found->second;
    const int new_index = static_cast<int>(mesh_->vertices.size());
    mesh_->vertices.push_back(v);
    lookup_.emplace(key, new_index);
    return new_index;
  }

 private:
  TriangleMesh* mesh_;
  std::map<std::array<std::uint32_t, 3>, int> lookup_;
};

// Adds the triangles of `node` and its children, moved into the scene's root frame. A mirroring
// transform (negative determinant) reverses the corners so the triangles keep facing outwards.
void addNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
             const std::string& path, VertexWelder* welder, TriangleMesh* mesh) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  const bool mirrored = transform.Determinant() < 0.0f;
  for (unsigned int n = 0; n < node.mNumMeshes; ++n) {
    const aiMesh* part = scene.mMeshes[node.mMeshes[n]];
    for (unsigned int f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      Eigen::Vector3i tri;
      for (int k = 0; k < 3; ++k) {
        const unsigned int i = face.mIndices[k];
        if (i >= part->mNumVertices) {
          throw Error("Mesh file '" + path + "' has a face referring to a missing vertex.");
        }
        tri[k] = welder->index(transform * part->mVertices[i]);
      }
      if (mirrored) std::swap(tri[1], tri[2]);
      mesh->triangles.push_back(tri);
    }
  }
  for (unsigned int c = 0; c < node.mNumChildren; ++c) {
    addNode(scene, *node.mChildren[c], transform, path, welder, mesh);
  }
}

}  // namespace

TriangleMesh loadMesh(const std::string& path) {
  checkReadableFile(path);

  Assimp::Importer importer;
  // Only positions matter; dropping normals and colours lets assimp's joining step work too.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_COLORS |
                                                          aiComponent_TEXCOORDS |
                                                          aiComponent_TANGENTS_AND_BITANGENTS);
  // The object frame is the file's own frame: assimp would otherwise rotate Z-up Collada files
  // into its Y-up convention.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // Node transforms are applied below rather than by aiProcess_PreTransformVertices, which
  // rejects files without faces (point clouds) with a message about "orphaned meshes" instead of
  // letting us say what is wrong.
  const unsigned int flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                             aiProcess_RemoveComponent | aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(path, flags);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "unknown format";
    throw Error("Mesh file '" + path + "' cannot be read as a mesh: " + reason + ".");
  }

  TriangleMesh mesh;
  VertexWelder welder(&mesh);
  addNode(*scene, *scene->mRootNode, aiMatrix4x4(), path, &welder, &mesh);
  if (mesh.triangles.empty()) {
    throw Error("Mesh file '" + path +
                "' contains no triangles (only points or lines, or no geometry at all).");
  }
  for (const auto& v : mesh.vertices) {
    if (!v.allFinite()) {
      throw Error("Mesh file '" + path + "' contains a vertex with a non-finite coordinate.");
    }
  }
  return mesh;
}

void saveMeshPly(const TriangleMesh& mesh, const std::string& path, PlyEncoding encoding) {
  const auto vertex_count = static_cast<long long>(mesh.vertices.size());
  for (const auto& tri : mesh.triangles) {
    if ((tri.array() < 0).any() || (tri.array() >= vertex_count).any()) {
      throw Error("Cannot write mesh file '" + path +
                  "': a triangle refers to a vertex outside the vertex list.");
    }
  }
  const bool binary = encoding == PlyEncoding::kBinaryLittleEndian;
  std::ofstream out(path, binary ? std::ios::binary : std::ios::out);
  if (!out) {
    throw Error("Mesh file '" + path + "' cannot be opened for writing.");
  }
  out << "ply\n"
      << "format " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
      << "comment view_direction_classification mesh, metres\n"
      << "element vertex " << mesh.vertices.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "element face " << mesh.triangles.size() << "\n"
      << "property list uchar int vertex_indices\n"
      << "end_header\n";
  if (binary) {
    static_assert(sizeof(float) == 4 && sizeof(std::int32_t) == 4, "PLY needs 32-bit types");
    for (const auto& v : mesh.vertices) {
      const float xyz[3] = {v.x(), v.y(), v.z()};
      out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    }
    for (const auto& tri : mesh.triangles) {
      const std::uint8_t count = 3;
      const std::int32_t indices[3] = {tri[0], tri[1], tri[2]};
      out.write(reinterpret_cast<const char*>(&count), 1);
      out.write(reinterpret_cast<const char*>(indices), sizeof(indices));
    }
  } else {
    out.precision(9);  // round-trips a float exactly
    for (const auto& v : mesh.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& tri : mesh.triangles) {
      out << "3 " << tri[0] << ' ' << tri[1] << ' ' << tri[2] << '\n';
    }
  }
  out.flush();
  if (!out) {
    throw Error("Mesh file '" + path + "' could not be written completely (disk full?).");
  }
}

}  // namespace vdc
