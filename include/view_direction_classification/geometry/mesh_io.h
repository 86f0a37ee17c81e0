#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// Loads a triangle mesh (PLY, STL, OBJ, OFF and the other formats assimp reads) in metres.
// Polygons are triangulated, node transforms are applied, all parts are merged into one mesh and
// vertices at identical positions are joined (STL and per-face-normal files repeat them), so
// the topology checks of mesh_check.h see the real surface. Throws vdc::Error naming the file
// and what is wrong if it is missing, empty, larger than 1 GiB, damaged (a cut file, counts or
// indices the file does not back, a value that is no number), or holds no triangles (e.g. a
// point cloud). PLY (ASCII and binary of either byte order), OFF, OBJ and STL (ASCII and binary)
// are read by the package's own readers, which no damaged file crashes or hangs (fuzzed: fuzz/);
// other formats go to assimp.
TriangleMesh loadMesh(const std::string& path);

enum class MeshFormat { kPly, kOff, kObj, kStl };

// The format loadMesh reads a file as: PLY if it starts with the line "ply", else by its
// extension (any case); nullopt for the formats left to assimp.
std::optional<MeshFormat> meshFormatOf(const std::string& path, std::string_view first_bytes);

// A mesh from the bytes of a file of `format` (what loadMesh does after reading the file);
// `name` is the file's name in messages. Throws vdc::Error as loadMesh does.
TriangleMesh parseMesh(std::string_view bytes, MeshFormat format, const std::string& name);

enum class PlyEncoding { kBinaryLittleEndian, kAscii };

// Writes the mesh as PLY (float x y z, `vertex_indices` as uchar/int lists), readable by assimp,
// MeshLab and PCL. Throws vdc::Error naming the file if it cannot be written or the mesh has
// invalid indices.
void saveMeshPly(const TriangleMesh& mesh, const std::string& path,
                 PlyEncoding encoding = PlyEncoding::kBinaryLittleEndian);

}  // namespace vdc
