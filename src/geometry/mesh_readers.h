#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vdc::mesh_readers {

// The readers of the four formats a user is expected to bring (PLY, OFF, OBJ, STL). They are
// ours rather than assimp's because assimp 5.2 cannot be trusted with a damaged file: the mug's
// binary PLY cut to half its length crashed it in post-processing, and of 150 damaged copies
// (scripts/damaged_mesh_check.py) of the mug as binary PLY 146 crashed it and 2 hung it, as ASCII
// PLY 83 and as OFF 28 crashed it. Checking a PLY before assimp reads it would mean parsing all
// of it (list counts vary per face, so sizes and indices can only be checked by walking the
// body), and a file that passed would then be parsed again by the code that could not be
// trusted. assimp did not crash on damaged OBJ and STL files, but it loaded cut ones silently;
// these two formats are short to read, so they follow the same rules. Each reader walks the
// bytes once with bounds checks, never trusts a count before the bytes that back it are there,
// and throws vdc::Error with what is wrong (without the file's name, which the caller adds).

// What a reader yields: positions and polygons as lists of corner indices, not yet checked
// against the vertex count (mesh_io.cpp checks, triangulates and joins vertices).
struct IndexedPolygons {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::int32_t> corners;         // every polygon's corners, one polygon after another
  std::vector<std::uint32_t> corner_counts;  // corners per polygon
  std::size_t skipped_polygons = 0;          // points and lines (fewer than 3 corners)

  void addPolygon(const std::int32_t* first, std::size_t count);
};

// Limits a file cannot talk a reader past: a polygon with more corners is refused (its
// triangulation costs the square of its size), as is a vertex index beyond what an int holds.
constexpr std::size_t kMaxPolygonCorners = 1024;
constexpr std::int64_t kMaxVertexIndex = 0x7fffffff;

// A coordinate as float; beyond float's range it becomes an infinity (refused later as
// non-finite) rather than the undefined behaviour of a plain conversion.
float toCoordinate(double value);

IndexedPolygons readPly(std::string_view bytes);
IndexedPolygons readOff(std::string_view bytes);
IndexedPolygons readObj(std::string_view bytes);
// Binary (80-byte header, count, 50 bytes per triangle) or ASCII ("solid ... endsolid").
IndexedPolygons readStl(std::string_view bytes);
// Any other format assimp knows, from the file (assimp_mesh_reader.cpp).
IndexedPolygons readWithAssimp(const std::string& path);

}  // namespace vdc::mesh_readers
