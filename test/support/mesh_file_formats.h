#pragma once

// A triangle mesh written in every format loadMesh reads with its own readers, as the bytes of a
// file, and randomly damaged copies of such bytes: the mesh loading tests and the fuzz seeds.

#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc::test {

struct MeshFileFormat {
  const char* name;       // for test messages
  const char* extension;  // what a file of it is called
  MeshFormat format;
};

inline const std::vector<MeshFileFormat>& meshFileFormats() {
  static const std::vector<MeshFileFormat> formats = {
      {"ascii_ply", ".ply", MeshFormat::kPly},
      {"binary_little_endian_ply", ".ply", MeshFormat::kPly},
      {"binary_big_endian_ply", ".ply", MeshFormat::kPly},
      {"off", ".off", MeshFormat::kOff},
      {"obj", ".obj", MeshFormat::kObj},
      {"ascii_stl", ".stl", MeshFormat::kStl},
      {"binary_stl", ".stl", MeshFormat::kStl}};
  return formats;
}

namespace detail {

template <typename T>
void appendBinary(std::string* out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  }
  out->append(raw, sizeof(T));
}

inline std::string plyHeader(const TriangleMesh& mesh, const char* encoding) {
  std::ostringstream out;
  out << "ply\nformat " << encoding << " 1.0\nelement vertex " << mesh.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
      << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  return out.str();
}

}  // namespace detail

// The bytes of `mesh` as a file of the format called `name` (one of meshFileFormats()).
inline std::string meshFileBytes(const TriangleMesh& mesh, const std::string& name) {
  std::ostringstream text;
  text.precision(9);  // round-trips a float
  std::string binary;
  if (name == "ascii_ply") {
    text << detail::plyHeader(mesh, "ascii");
    for (const auto& v : mesh.vertices) text << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : mesh.triangles) text << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  } else if (name == "binary_little_endian_ply" || name == "binary_big_endian_ply") {
    const bool big = name == "binary_big_endian_ply";
    binary = detail::plyHeader(mesh, big ? "binary_big_endian" : "binary_little_endian");
    for (const auto& v : mesh.vertices) {
      for (int k = 0; k < 3; ++k) detail::appendBinary(&binary, v[k], big);
    }
    for (const auto& t : mesh.triangles) {
      binary.push_back(3);
      for (int k = 0; k < 3; ++k) detail::appendBinary<std::int32_t>(&binary, t[k], big);
    }
    return binary;
  } else if (name == "off") {
    text << "OFF\n# written by the tests\n"
         << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
    for (const auto& v : mesh.vertices) text << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : mesh.triangles) text << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  } else if (name == "obj") {
    text << "# written by the tests\no mesh\n";
    for (const auto& v : mesh.vertices)
      text << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : mesh.triangles) {
      text << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
  } else if (name == "ascii_stl") {
    text << "solid mesh\n";
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Eigen::Vector3f n = mesh.triangleNormal(t);
      text << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n outer loop\n";
      for (int k = 0; k < 3; ++k) {
        const auto& v = mesh.vertices[mesh.triangles[t][k]];
        text << "  vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
      }
      text << " endloop\nendfacet\n";
    }
    text << "endsolid mesh\n";
  } else if (name == "binary_stl") {
    binary = std::string(80, ' ');
    detail::appendBinary<std::uint32_t>(&binary, mesh.triangles.size(), false);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Eigen::Vector3f n = mesh.triangleNormal(t);
      for (int k = 0; k < 3; ++k) detail::appendBinary(&binary, n[k], false);
      for (int c = 0; c < 3; ++c) {
        const auto& v = mesh.vertices[mesh.triangles[t][c]];
        for (int k = 0; k < 3; ++k) detail::appendBinary(&binary, v[k], false);
      }
      detail::appendBinary<std::uint16_t>(&binary, 0, false);
    }
    return binary;
  }
  return text.str();
}

// `bytes` with up to 16 bytes overwritten, cut short, or a stretch of itself spliced in (as
// scripts/damaged_mesh_check.py damages whole files).
inline std::string damagedCopy(const std::string& bytes, std::mt19937* rng) {
  std::string data = bytes;
  auto uniform = [rng](std::size_t low, std::size_t high) {
    return std::uniform_int_distribution<std::size_t>(low, high)(*rng);
  };
  switch (uniform(0, 2)) {
    case 0:
      for (std::size_t n = uniform(1, 16); n > 0; --n) {
        data[uniform(0, data.size() - 1)] = static_cast<char>(uniform(0, 255));
      }
      break;
    case 1:
      data.resize(uniform(1, data.size() - 1));
      break;
    default: {
      const std::size_t start = uniform(0, data.size() - 1);
      const std::size_t length = uniform(1, std::min<std::size_t>(4096, data.size() - start));
      data.insert(uniform(0, data.size()), bytes.substr(start, length));
    }
  }
  return data;
}

}  // namespace vdc::test
