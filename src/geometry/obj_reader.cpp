// Wavefront OBJ: the geometry of "v X Y Z [W | R G B]" and "f V[/T][/N] ..." lines (indices from
// 1, negative ones counted back from the latest vertex); '#' starts a comment; every other line
// (texture coordinates, normals, groups, materials, lines, points) is ignored, as it carries no
// surface.
#include <string>

#include "mesh_readers.h"
#include "text_scanner.h"
#include "view_direction_classification/common/error.h"

namespace vdc::mesh_readers {
namespace {

[[noreturn]] void lineError(std::size_t line, const std::string& what) {
  throw Error("line " + std::to_string(line) + ": " + what);
}

// The vertex index of a face corner "V", "V/T", "V//N" or "V/T/N", zero-based.
std::int32_t cornerIndex(std::string_view corner, std::size_t vertices_so_far, std::size_t line) {
  const std::string_view vertex = corner.substr(0, corner.find('/'));
  std::int64_t index = 0;
  if (!parseInteger(vertex, &index) || index == 0 || index > kMaxVertexIndex ||
      index < -kMaxVertexIndex) {
    lineError(line, quoted(corner) + " is not a vertex index");
  }
  if (index < 0) {
    // Relative: -1 is the latest vertex.
    index += static_cast<std::int64_t>(vertices_so_far);
    if (index < 0) {
      lineError(line, quoted(corner) + " refers to a vertex before the first");
    }
    return static_cast<std::int32_t>(index);
  }
  return static_cast<std::int32_t>(index - 1);
}

}  // namespace

IndexedPolygons readObj(std::string_view bytes) {
  TextScanner scanner(bytes);
  IndexedPolygons mesh;
  std::vector<std::int32_t> corners;
  std::string_view line;
  while (scanner.nextLine(&line)) {
    const auto words = splitWords(withoutComment(line, '#'), kMaxPolygonCorners + 2);
    if (words.empty()) continue;
    const std::size_t number = scanner.lineNumber();
    if (words[0] == "v") {
      double xyz[3];
      for (int k = 0; k < 3; ++k) {
        if (k + 1 >= static_cast<int>(words.size()) || !parseReal(words[k + 1], &xyz[k])) {
          lineError(number, "expected a vertex 'v X Y Z'");
        }
      }
      if (mesh.vertices.size() > static_cast<std::size_t>(kMaxVertexIndex)) {
        lineError(number, "more vertices than this loader supports");
      }
      mesh.vertices.emplace_back(toCoordinate(xyz[0]), toCoordinate(xyz[1]), toCoordinate(xyz[2]));
    } else if (words[0] == "f") {
      if (words.size() > kMaxPolygonCorners + 1) {
        lineError(number, "a face of more than the " + std::to_string(kMaxPolygonCorners) +
                              " corners supported");
      }
      corners.clear();
      for (std::size_t k = 1; k < words.size(); ++k) {
        corners.push_back(cornerIndex(words[k], mesh.vertices.size(), number));
      }
      mesh.addPolygon(corners.data(), corners.size());
    }
  }
  return mesh;
}

}  // namespace vdc::mesh_readers
