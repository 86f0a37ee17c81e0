#include "view_direction_classification/geometry/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Per undirected edge: how many triangles use it, and how many walk it from the lower index to
// the higher one (a consistently oriented two-triangle edge is walked once each way).
struct EdgeUse {
  int triangles = 0;
  int forward = 0;
};

std::uint64_t edgeKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

// A triangle whose area is below this fraction of its squared longest edge is a sliver with no
// usable normal.
constexpr double kDegenerateRelativeArea = 1e-12;

std::string formatMetres(double value) {
  std::ostringstream out;
  out << value << " m";
  return out.str();
}

}  // namespace

MeshCheck checkMesh(const TriangleMesh& mesh) {
  const auto vertex_count = static_cast<long long>(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      throw Error("mesh vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int index = mesh.triangles[t][k];
      if (index < 0 || index >= vertex_count) {
        throw Error("mesh triangle " + std::to_string(t) + " refers to vertex " +
                    std::to_string(index) + " but the mesh has only " +
                    std::to_string(vertex_count) + " vertices");
      }
    }
  }

  MeshCheck check;
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(mesh.triangles.size() * 2);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.vertices[tri[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[tri[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[tri[2]].cast<double>();
    const double longest_sq =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const bool repeated = tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
    if (repeated || !(0.5 * (b - a).cross(c - a).norm() > kDegenerateRelativeArea * longest_sq)) {
      ++check.degenerate_triangles;
    }
    if (repeated) continue;  // its "edges" are not edges of a surface
    for (int k = 0; k < 3; ++k) {
      const int from = tri[k];
      const int to = tri[(k + 1) % 3];
      EdgeUse& use = edges[edgeKey(from, to)];
      ++use.triangles;
      if (from < to) ++use.forward;
    }
  }
  for (const auto& entry : edges) {
    const EdgeUse& use = entry.second;
    if (use.triangles == 1) ++check.boundary_edges;
    if (use.triangles > 2) ++check.non_manifold_edges;
    if (use.triangles == 2 && use.forward != 1) ++check.inconsistent_edges;
  }
  check.watertight =
      !mesh.triangles.empty() && check.boundary_edges == 0 && check.non_manifold_edges == 0;
  if (!mesh.vertices.empty()) check.largest_extent = mesh.bounds().sizes().maxCoeff();

  if (check.boundary_edges > 0) {
    check.warnings.push_back("the surface is open: " + std::to_string(check.boundary_edges) +
                             " edges belong to only one triangle");
  }
  if (check.non_manifold_edges > 0) {
    check.warnings.push_back(
        "the surface is non-manifold: " + std::to_string(check.non_manifold_edges) +
        " edges are shared by three or more triangles");
  }
  if (check.inconsistent_edges > 0) {
    check.warnings.push_back("the triangles are inconsistently oriented along " +
                             std::to_string(check.inconsistent_edges) +
                             " edges (some normals may point inwards)");
  }
  if (check.degenerate_triangles > 0) {
    check.warnings.push_back(std::to_string(check.degenerate_triangles) +
                             " triangles are degenerate (zero area)");
  }
  return check;
}

std::vector<std::string> validateObjectMesh(const TriangleMesh& mesh, const std::string& name) {
  if (mesh.triangles.empty()) {
    throw Error("Mesh '" + name + "' contains no triangles.");
  }
  MeshCheck check;
  try {
    check = checkMesh(mesh);
  } catch (const Error& e) {
    throw Error("Mesh '" + name + "' is invalid: " + e.what() + ".");
  }
  if (!(mesh.area() > 0.0)) {
    throw Error("Mesh '" + name + "' has zero surface area (all triangles are degenerate).");
  }
  if (check.largest_extent > kMaxObjectExtent) {
    throw Error("Mesh '" + name + "' is " + formatMetres(check.largest_extent) +
                " across, which looks like millimetres; the package expects metres (scale it "
                "by 0.001).");
  }
  if (check.largest_extent < kMinObjectExtent) {
    throw Error("Mesh '" + name + "' is only " + formatMetres(check.largest_extent) +
                " across; the package expects metres and objects of at least " +
                formatMetres(kMinObjectExtent) + ".");
  }
  std::vector<std::string> warnings;
  warnings.reserve(check.warnings.size());
  for (const auto& w : check.warnings) warnings.push_back("Mesh '" + name + "': " + w + ".");
  return warnings;
}

}  // namespace vdc
