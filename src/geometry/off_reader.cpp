// OFF (Geomview's Object File Format, ASCII): "[ST][C][N]OFF", the counts "vertices faces edges",
// one vertex per line (x y z, then normals, colours or texture coordinates, ignored), one face per
// line ("n i_1 ... i_n", then an optional colour, ignored). '#' starts a comment. Read line by
// line, because the per-vertex and per-face extras vary in length.
#include <string>

#include "mesh_readers.h"
#include "text_scanner.h"
#include "view_direction_classification/common/error.h"

namespace vdc::mesh_readers {
namespace {

[[noreturn]] void lineError(std::size_t line, const std::string& what) {
  throw Error("line " + std::to_string(line) + ": " + what);
}

// The next line with something on it (comments removed), split into at most `limit` words.
bool nextWords(TextScanner* scanner, std::size_t limit, std::vector<std::string_view>* words) {
  std::string_view line;
  while (scanner->nextLine(&line)) {
    *words = splitWords(withoutComment(line, '#'), limit);
    if (!words->empty()) return true;
  }
  return false;
}

// "OFF" with any of the prefixes ST (texture coordinates), C (colours), N (normals); "4OFF"
// (homogeneous coordinates), "nOFF" (other dimensions) and binary OFF are not supported.
bool isOffKeyword(std::string_view word) {
  if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return false;
  std::string_view prefix = word.substr(0, word.size() - 3);
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  if (!prefix.empty() && prefix[0] == 'C') prefix.remove_prefix(1);
  if (!prefix.empty() && prefix[0] == 'N') prefix.remove_prefix(1);
  return prefix.empty();
}

std::int64_t count(std::string_view word, std::size_t line, const char* what) {
  std::int64_t value = 0;
  if (!parseInteger(word, &value) || value < 0 || value > kMaxVertexIndex) {
    lineError(line, quoted(word) + " is not a " + what + " count");
  }
  return value;
}

}  // namespace

IndexedPolygons readOff(std::string_view bytes) {
  TextScanner scanner(bytes);
  std::vector<std::string_view> words;
  if (!nextWords(&scanner, 5, &words) || !isOffKeyword(words[0])) {
    throw Error("it does not start with 'OFF' (4OFF, nOFF and binary OFF are not supported)");
  }
  if (words.size() > 1 && words[1] == "BINARY") throw Error("binary OFF is not supported");
  // The counts may follow the keyword on its line.
  words.erase(words.begin());
  if (words.empty() && !nextWords(&scanner, 4, &words)) throw Error("the counts line is missing");
  if (words.size() < 2) lineError(scanner.lineNumber(), "expected 'VERTICES FACES [EDGES]'");
  const std::int64_t vertex_count = count(words[0], scanner.lineNumber(), "vertex");
  const std::int64_t face_count = count(words[1], scanner.lineNumber(), "face");

  IndexedPolygons mesh;
  // Every vertex line takes at least 6 bytes ("0 0 0\n"): reserve no more than the file backs.
  mesh.vertices.reserve(static_cast<std::size_t>(
      std::min<std::int64_t>(vertex_count, static_cast<std::int64_t>(bytes.size() / 6))));
  for (std::int64_t v = 0; v < vertex_count; ++v) {
    if (!nextWords(&scanner, 3, &words)) {
      throw Error("the file ends after " + std::to_string(v) + " of " +
                  std::to_string(vertex_count) + " vertices (a cut file?)");
    }
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
      if (k >= static_cast<int>(words.size()) || !parseReal(words[k], &xyz[k])) {
        lineError(scanner.lineNumber(), "expected a vertex 'X Y Z'");
      }
    }
    mesh.vertices.emplace_back(toCoordinate(xyz[0]), toCoordinate(xyz[1]), toCoordinate(xyz[2]));
  }

  std::vector<std::int32_t> corners;
  for (std::int64_t f = 0; f < face_count; ++f) {
    if (!nextWords(&scanner, kMaxPolygonCorners + 1, &words)) {
      throw Error("the file ends after " + std::to_string(f) + " of " + std::to_string(face_count) +
                  " faces (a cut file?)");
    }
    const std::size_t line = scanner.lineNumber();
    std::int64_t n = 0;
    if (!parseInteger(words[0], &n) || n < 0) lineError(line, "expected a face 'N I_1 ... I_N'");
    if (static_cast<std::uint64_t>(n) > kMaxPolygonCorners) {
      lineError(line, "a face of " + std::to_string(n) + " corners, more than the " +
                          std::to_string(kMaxPolygonCorners) + " supported");
    }
    if (static_cast<std::size_t>(n) + 1 > words.size()) {
      lineError(line, "the face lists fewer than its " + std::to_string(n) + " corners");
    }
    corners.clear();
    for (std::int64_t k = 1; k <= n; ++k) {
      std::int64_t index = 0;
      if (!parseInteger(words[k], &index) || index < 0 || index > kMaxVertexIndex) {
        lineError(line, quoted(words[k]) + " is not a vertex index");
      }
      corners.push_back(static_cast<std::int32_t>(index));
    }
    mesh.addPolygon(corners.data(), corners.size());
  }
  return mesh;
}

}  // namespace vdc::mesh_readers
