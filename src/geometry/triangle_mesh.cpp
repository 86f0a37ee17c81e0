#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {
namespace {

// Cross product of the two edges from vertex 0, in double: areas of millimetre-sized triangles
// lose too many digits in float.
Eigen::Vector3d edgeCross(const TriangleMesh& mesh, std::size_t t) {
  const Eigen::Vector3i& tri = mesh.triangles[t];
  const Eigen::Vector3d a = mesh.vertices[tri[0]].cast<double>();
  const Eigen::Vector3d b = mesh.vertices[tri[1]].cast<double>();
  const Eigen::Vector3d c = mesh.vertices[tri[2]].cast<double>();
  return (b - a).cross(c - a);
}

}  // namespace

double TriangleMesh::area() const {
  double total = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) total += triangleArea(t);
  return total;
}

Eigen::AlignedBox3f TriangleMesh::bounds() const {
  Eigen::AlignedBox3f box;  // default-constructed box is empty
  for (const auto& v : vertices) box.extend(v);
  return box;
}

double TriangleMesh::triangleArea(std::size_t t) const { return 0.5 * edgeCross(*this, t).norm(); }

Eigen::Vector3f TriangleMesh::triangleNormal(std::size_t t) const {
  const Eigen::Vector3d n = edgeCross(*this, t);
  const double length = n.norm();
  if (!(length > 0.0)) return Eigen::Vector3f::Zero();
  return (n / length).cast<float>();
}

double TriangleMesh::signedVolume() const {
  double volume = 0.0;
  for (const auto& tri : triangles) {
    const Eigen::Vector3d a = vertices[tri[0]].cast<double>();
    const Eigen::Vector3d b = vertices[tri[1]].cast<double>();
    const Eigen::Vector3d c = vertices[tri[2]].cast<double>();
    volume += a.dot(b.cross(c));
  }
  return volume / 6.0;
}

void TriangleMesh::append(const TriangleMesh& other) {
  const int offset = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const auto& tri : other.triangles) {
    triangles.push_back(tri + Eigen::Vector3i::Constant(offset));
  }
}

}  // namespace vdc
