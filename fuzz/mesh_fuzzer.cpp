// libFuzzer target: mesh loading (vdc::parseMesh, what vdc::loadMesh does with a file's bytes)
// for the four formats the package reads itself. The first byte picks the format (PLY, OFF, OBJ,
// STL; modulo 4), the rest are the file. A damaged file must throw vdc::Error; a loaded mesh must
// have finite vertices and triangle indices inside its vertex list, and pass to `vdc mesh
// check`'s report (checkMesh, validateObjectMesh) without crashing.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_check.h"
#include "view_direction_classification/geometry/mesh_io.h"

namespace {

void checkLoadedMesh(const vdc::TriangleMesh& mesh) {
  if (mesh.empty()) std::abort();  // parseMesh refuses a file without triangles
  for (const auto& vertex : mesh.vertices) {
    if (!vertex.allFinite()) std::abort();
  }
  const int vertices = static_cast<int>(mesh.vertices.size());
  for (const auto& triangle : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (triangle[k] < 0 || triangle[k] >= vertices) std::abort();
    }
  }
  vdc::checkMesh(mesh);
  try {
    vdc::validateObjectMesh(mesh, "fuzz");
  } catch (const vdc::Error&) {
    // a scale outside the object limits: refused with a message
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  if (size == 0) return 0;
  static const vdc::MeshFormat kFormats[] = {vdc::MeshFormat::kPly, vdc::MeshFormat::kOff,
                                             vdc::MeshFormat::kObj, vdc::MeshFormat::kStl};
  const vdc::MeshFormat format = kFormats[bytes[0] % 4];
  const std::string_view file(reinterpret_cast<const char*>(bytes + 1), size - 1);
  try {
    checkLoadedMesh(vdc::parseMesh(file, format, "fuzz"));
  } catch (const vdc::Error&) {
    // refused with a message naming what is wrong
  }
  return 0;
}
