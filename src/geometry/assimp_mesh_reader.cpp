// The formats the own readers do not cover (Collada, glTF, 3DS, ...), read with assimp. assimp
// cannot be trusted with damaged files (see mesh_readers.h); its own data-structure validation
// runs first, so an importer's inconsistent output is refused before post-processing, which
// crashed on the damaged PLY files. These formats are not fuzzed: PLY, OFF, OBJ and STL are.
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "mesh_readers.h"
#include "view_direction_classification/common/error.h"

namespace vdc::mesh_readers {
namespace {

// Adds the triangles of `node` and its children, moved into the scene's root frame. A mirroring
// transform (negative determinant) reverses the corners so the triangles keep facing outwards.
void addNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
             IndexedPolygons* mesh) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  const bool mirrored = transform.Determinant() < 0.0f;
  for (unsigned int n = 0; n < node.mNumMeshes; ++n) {
    const aiMesh* part = scene.mMeshes[node.mMeshes[n]];
    for (unsigned int f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) {  // points and lines carry no surface
        mesh->addPolygon(nullptr, 0);
        continue;
      }
      std::int32_t corners[3];
      for (int k = 0; k < 3; ++k) {
        const unsigned int i = face.mIndices[k];
        if (i >= part->mNumVertices) throw Error("a face refers to a missing vertex");
        const aiVector3D p = transform * part->mVertices[i];
        corners[k] = static_cast<std::int32_t>(mesh->vertices.size());
        mesh->vertices.emplace_back(p.x, p.y, p.z);
      }
      if (mirrored) std::swap(corners[1], corners[2]);
      mesh->addPolygon(corners, 3);
    }
  }
  for (unsigned int c = 0; c < node.mNumChildren; ++c) {
    addNode(scene, *node.mChildren[c], transform, mesh);
  }
}

}  // namespace

IndexedPolygons readWithAssimp(const std::string& path) {
  Assimp::Importer importer;
  // The object frame is the file's own frame: assimp would otherwise rotate Z-up Collada files
  // into its Y-up convention.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // Node transforms are applied below rather than by aiProcess_PreTransformVertices, which
  // rejects files without faces (point clouds) with a message about "orphaned meshes" instead of
  // letting us say what is wrong. Vertices are joined by the caller, across all parts.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_Triangulate);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "unknown format";
    throw Error(reason);
  }
  IndexedPolygons mesh;
  addNode(*scene, *scene->mRootNode, aiMatrix4x4(), &mesh);
  return mesh;
}

}  // namespace vdc::mesh_readers
