#pragma once

#include <string>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Loads a triangle mesh (PLY, STL, OBJ, OFF and the other formats assimp reads) in metres.
// Polygons are triangulated, node transforms are applied, all parts are merged into one mesh and
// vertices at identical positions are joined (STL and per-face-normal files repeat them), so
// the topology checks of mesh_check.h see the real surface. Throws vdc::Error naming the file
// if it is missing, empty, unreadable, or holds no triangles (e.g. a point cloud).
TriangleMesh loadMesh(const std::string& path);

enum class PlyEncoding { kBinaryLittleEndian, kAscii };

// Writes the mesh as PLY (float x y z, `vertex_indices` as uchar/int lists), readable by assimp,
// MeshLab and PCL. Throws vdc::Error naming the file if it cannot be written or the mesh has
// invalid indices.
void saveMeshPly(const TriangleMesh& mesh, const std::string& path,
                 PlyEncoding encoding = PlyEncoding::kBinaryLittleEndian);

}  // namespace vdc
