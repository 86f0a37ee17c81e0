// STL, binary (80-byte header, a little-endian uint32 triangle count, 50 bytes per triangle:
// normal, three corners, attribute) or ASCII ("solid NAME", facets of "vertex X Y Z" lines,
// "endsolid"). STL has no shared vertices: every facet gets three of its own and mesh_io.cpp
// joins the identical ones.
#include <cstring>
#include <string>

#include "mesh_readers.h"
#include "text_scanner.h"
#include "view_direction_classification/common/error.h"

namespace vdc::mesh_readers {
namespace {

constexpr std::size_t kBinaryHeaderBytes = 84;
constexpr std::size_t kBinaryTriangleBytes = 50;

std::uint32_t triangleCount(std::string_view bytes) {
  unsigned char raw[4];
  std::memcpy(raw, bytes.data() + 80, 4);
  return std::uint32_t(raw[0]) | std::uint32_t(raw[1]) << 8 | std::uint32_t(raw[2]) << 16 |
         std::uint32_t(raw[3]) << 24;
}

float littleEndianFloat(const char* at) {
  unsigned char raw[4];
  std::memcpy(raw, at, 4);
  const std::uint32_t bits = std::uint32_t(raw[0]) | std::uint32_t(raw[1]) << 8 |
                             std::uint32_t(raw[2]) << 16 | std::uint32_t(raw[3]) << 24;
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

std::size_t binarySize(std::uint64_t triangles) {
  return kBinaryHeaderBytes + kBinaryTriangleBytes * triangles;
}

// Binary STL headers may begin with "solid" too (some CAD exporters write it), so a file is
// binary if its size is exactly what its triangle count says, else ASCII if it starts with
// "solid".
bool isBinary(std::string_view bytes) {
  if (bytes.size() >= kBinaryHeaderBytes && bytes.size() == binarySize(triangleCount(bytes))) {
    return true;
  }
  std::size_t start = 0;
  while (start < bytes.size() && isSpace(bytes[start])) ++start;
  return bytes.substr(start, 5) != "solid";
}

IndexedPolygons readBinary(std::string_view bytes) {
  if (bytes.size() < kBinaryHeaderBytes) {
    throw Error("it is " + std::to_string(bytes.size()) +
                " bytes long, shorter than a binary STL header (84 bytes), and not ASCII STL");
  }
  const std::uint32_t triangles = triangleCount(bytes);
  // Some writers pad the end; a file shorter than its count says is cut.
  if (bytes.size() < binarySize(triangles)) {
    throw Error("its header declares " + std::to_string(triangles) + " triangles (" +
                std::to_string(binarySize(triangles)) + " bytes), but it has " +
                std::to_string(bytes.size()) + " bytes (a cut file?)");
  }
  if (3 * std::uint64_t(triangles) > static_cast<std::uint64_t>(kMaxVertexIndex)) {
    throw Error("its header declares " + std::to_string(triangles) +
                " triangles, more than this loader supports");
  }
  IndexedPolygons mesh;
  mesh.vertices.reserve(3 * std::size_t(triangles));
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const char* corners = bytes.data() + kBinaryHeaderBytes + kBinaryTriangleBytes * t + 12;
    std::int32_t indices[3];
    for (int k = 0; k < 3; ++k) {
      const char* xyz = corners + 12 * k;
      indices[k] = static_cast<std::int32_t>(mesh.vertices.size());
      mesh.vertices.emplace_back(littleEndianFloat(xyz), littleEndianFloat(xyz + 4),
                                 littleEndianFloat(xyz + 8));
    }
    mesh.addPolygon(indices, 3);
  }
  return mesh;
}

class AsciiStlParser {
 public:
  explicit AsciiStlParser(std::string_view bytes) : scanner_(bytes) {}

  IndexedPolygons parse() {
    expect("solid");
    std::string_view token;
    skipName(&token);
    while (true) {
      if (token == "facet") {
        readFacet();
        next(&token);
      } else if (token == "endsolid") {
        // Its name, then possibly another solid.
        while (next(&token) && token != "solid") {
        }
        if (token.empty()) return std::move(mesh_);
        skipName(&token);
      } else if (token.empty()) {
        throw Error("the file ends without 'endsolid' (a cut file?)");
      } else {
        fail("expected 'facet' or 'endsolid', found " + quoted(token));
      }
    }
  }

 private:
  // A solid's name may be several words, or none: everything up to the first "facet" or
  // "endsolid" (left in `token`; empty at the end of the file).
  void skipName(std::string_view* token) {
    while (next(token) && *token != "facet" && *token != "endsolid") {
    }
  }

  bool next(std::string_view* token) {
    if (scanner_.nextToken(token)) return true;
    *token = std::string_view();
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error("line " + std::to_string(scanner_.lineNumber()) + ": " + what);
  }

  void expect(const char* word) {
    std::string_view token;
    if (!next(&token))
      throw Error(std::string("the file ends where '") + word + "' should be (a cut file?)");
    if (token != word) {
      fail(std::string("expected '") + word + "\', found " + quoted(token));
    }
  }

  double number() {
    std::string_view token;
    double value = 0.0;
    if (!next(&token)) throw Error("the file ends inside a facet (a cut file?)");
    if (!parseReal(token, &value)) fail(quoted(token) + " is not a number");
    return value;
  }

  // "facet normal NX NY NZ outer loop vertex X Y Z (x3) endloop endfacet", "facet" read.
  void readFacet() {
    expect("normal");
    for (int k = 0; k < 3; ++k) number();
    expect("outer");
    expect("loop");
    std::int32_t indices[3];
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      const double x = number(), y = number(), z = number();
      indices[k] = static_cast<std::int32_t>(mesh_.vertices.size());
      mesh_.vertices.emplace_back(toCoordinate(x), toCoordinate(y), toCoordinate(z));
    }
    expect("endloop");
    expect("endfacet");
    if (mesh_.vertices.size() > static_cast<std::size_t>(kMaxVertexIndex) - 3) {
      fail("more facets than this loader supports");
    }
    mesh_.addPolygon(indices, 3);
  }

  TextScanner scanner_;
  IndexedPolygons mesh_;
};

}  // namespace

IndexedPolygons readStl(std::string_view bytes) {
  if (isBinary(bytes)) return readBinary(bytes);
  try {
    return AsciiStlParser(bytes).parse();
  } catch (const Error& error) {
    if (bytes.size() < kBinaryHeaderBytes) throw;
    // A binary file whose header starts with "solid" lands here if it is padded (then it is read
    // as binary) or cut (then both readings are reported, if it looks binary at all).
    const std::uint32_t triangles = triangleCount(bytes);
    if (bytes.size() >= binarySize(triangles)) return readBinary(bytes);
    if (bytes.find('\0') == std::string_view::npos) throw;
    throw Error(std::string("as ASCII STL (it starts with 'solid'): ") + error.what() +
                "; as binary STL its header declares " + std::to_string(triangles) +
                " triangles (" + std::to_string(binarySize(triangles)) + " bytes), but it has " +
                std::to_string(bytes.size()) + " bytes");
  }
}

}  // namespace vdc::mesh_readers
