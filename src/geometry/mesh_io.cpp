#include "view_direction_classification/geometry/mesh_io.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>
#include <unordered_map>
#include <utility>

#include "mesh_readers.h"
#include "polygon_triangulation.h"
#include "view_direction_classification/common/error.h"

// Binary PLY is written from the in-memory representation.
#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "saveMeshPly writes binary_little_endian PLY from memory and needs a little-endian target"
#endif

namespace vdc {
namespace {

namespace fs = std::filesystem;

// The whole file is read into memory; a mesh to train on is far smaller.
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(1) << 30;

std::uintmax_t checkReadableFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    throw Error("Mesh file '" + path + "' does not exist.");
  }
  if (!fs::is_regular_file(status)) {
    throw Error("Mesh file '" + path + "' is not a regular file.");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (size == 0 || ec) {
    throw Error("Mesh file '" + path + "' is empty.");
  }
  if (size > kMaxMeshFileBytes) {
    throw Error("Mesh file '" + path + "' is " + std::to_string(size >> 20) +
                " MiB, more than the 1024 MiB this loader reads.");
  }
  return size;
}

std::string readFile(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size))) {
    throw Error("Mesh file '" + path + "' cannot be read.");
  }
  return bytes;
}

std::string lowerCaseExtension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

const char* formatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::kPly:
      return "PLY";
    case MeshFormat::kOff:
      return "OFF";
    case MeshFormat::kObj:
      return "OBJ";
    case MeshFormat::kStl:
      return "STL";
  }
  return "mesh";
}

// Joins vertices with bit-identical coordinates across the whole file (STL repeats every
// corner, other formats may split parts or normals).
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh* mesh) : mesh_(mesh) {}

  int index(const Eigen::Vector3f& v) {
    std::array<std::uint32_t, 3> key;
    for (int k = 0; k < 3; ++k) {
      // +0.0f folds -0 into 0, so both spellings of zero are one vertex.
      const float coordinate = v[k] + 0.0f;
      std::memcpy(&key[k], &coordinate, sizeof(float));
    }
    const auto [found, inserted] =
        lookup_.try_emplace(key, static_cast<int>(mesh_->vertices.size()));
    if (inserted) mesh_->vertices.push_back(v);
    return found->second;
  }

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::uint32_t, 3>& key) const {
      std::uint64_t h = 1469598103934665603ull;
      for (std::uint32_t k : key) h = (h ^ k) * 1099511628211ull;
      return static_cast<std::size_t>(h);
    }
  };

  TriangleMesh* mesh_;
  std::unordered_map<std::array<std::uint32_t, 3>, int, KeyHash> lookup_;
};

// Checks every polygon's corners against the vertices, triangulates and joins identical
// vertices (only those a triangle uses are kept).
TriangleMesh assembleMesh(const mesh_readers::IndexedPolygons& polygons, const std::string& name) {
  const std::size_t vertex_count = polygons.vertices.size();
  std::vector<Eigen::Vector3i> triangles;
  std::size_t first = 0;
  for (std::size_t p = 0; p < polygons.corner_counts.size(); ++p) {
    const std::size_t count = polygons.corner_counts[p];
    const std::int32_t* corners = polygons.corners.data() + first;
    first += count;
    for (std::size_t k = 0; k < count; ++k) {
      const auto index = static_cast<std::size_t>(corners[k]);
      if (index >= vertex_count) {
        throw Error("Mesh file '" + name + "' has a face (number " + std::to_string(p) +
                    ") referring to vertex " + std::to_string(index) + ", but only " +
                    std::to_string(vertex_count) + " vertices.");
      }
      if (!polygons.vertices[index].allFinite()) {
        throw Error("Mesh file '" + name + "' contains a vertex with a non-finite coordinate.");
      }
    }
    triangulatePolygon(polygons.vertices, corners, count, &triangles);
  }
  if (triangles.empty()) {
    throw Error("Mesh file '" + name +
                "' contains no triangles (only points or lines, or no geometry at all).");
  }
  TriangleMesh mesh;
  mesh.triangles.reserve(triangles.size());
  VertexWelder welder(&mesh);
  for (const Eigen::Vector3i& triangle : triangles) {
    mesh.triangles.emplace_back(welder.index(polygons.vertices[triangle[0]]),
                                welder.index(polygons.vertices[triangle[1]]),
                                welder.index(polygons.vertices[triangle[2]]));
  }
  return mesh;
}

}  // namespace

namespace mesh_readers {

void IndexedPolygons::addPolygon(const std::int32_t* first, std::size_t count) {
  if (count < 3) {
    ++skipped_polygons;
    return;
  }
  corners.insert(corners.end(), first, first + count);
  corner_counts.push_back(static_cast<std::uint32_t>(count));
}

float toCoordinate(double value) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (value > kMax) return std::numeric_limits<float>::infinity();
  if (value < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(value);  // NaN stays NaN
}

}  // namespace mesh_readers

std::optional<MeshFormat> meshFormatOf(const std::string& path, std::string_view first_bytes) {
  if (first_bytes.substr(0, 4) == "ply\n" || first_bytes.substr(0, 5) == "ply\r\n") {
    return MeshFormat::kPly;
  }
  const std::string extension = lowerCaseExtension(path);
  if (extension == ".ply") return MeshFormat::kPly;
  if (extension == ".off") return MeshFormat::kOff;
  if (extension == ".obj") return MeshFormat::kObj;
  if (extension == ".stl") return MeshFormat::kStl;
  return std::nullopt;
}

TriangleMesh parseMesh(std::string_view bytes, MeshFormat format, const std::string& name) {
  mesh_readers::IndexedPolygons polygons;
  try {
    switch (format) {
      case MeshFormat::kPly:
        polygons = mesh_readers::readPly(bytes);
        break;
      case MeshFormat::kOff:
        polygons = mesh_readers::readOff(bytes);
        break;
      case MeshFormat::kObj:
        polygons = mesh_readers::readObj(bytes);
        break;
      case MeshFormat::kStl:
        polygons = mesh_readers::readStl(bytes);
        break;
    }
  } catch (const Error& error) {
    throw Error("Mesh file '" + name + "' is not a valid " + formatName(format) +
                " file: " + error.what() + ".");
  }
  return assembleMesh(polygons, name);
}

TriangleMesh loadMesh(const std::string& path) {
  const std::uintmax_t size = checkReadableFile(path);
  const std::string bytes = readFile(path, size);
  if (const std::optional<MeshFormat> format = meshFormatOf(path, bytes)) {
    return parseMesh(bytes, *format, path);
  }
  mesh_readers::IndexedPolygons polygons;
  try {
    polygons = mesh_readers::readWithAssimp(path);
  } catch (const Error& error) {
    throw Error("Mesh file '" + path + "' cannot be read as a mesh: " + error.what() + ".");
  }
  return assembleMesh(polygons, path);
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
