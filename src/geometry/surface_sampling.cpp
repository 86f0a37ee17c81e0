#include "view_direction_classification/geometry/surface_sampling.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/mesh_check.h"

namespace vdc {
namespace {

constexpr double kMaxSamples = 5e7;

// A stratum: a piece of one mesh triangle.
struct Cell {
  Eigen::Vector3d a, b, c;
  double area;
  int triangle;
};

// Bisects the longest edge until the piece is no larger than the target area and no edge is
// longer than twice the spacing. Longest-edge bisection keeps the pieces' angles bounded, so
// strata stay compact instead of becoming slivers on long thin triangles.
void splitIntoCells(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    int triangle, double max_area, double max_edge_sq, std::vector<Cell>* cells) {
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  const double longest = std::max({ab, bc, ca});
  if (area <= max_area && longest <= max_edge_sq) {
    if (area > 0.0) cells->push_back({a, b, c, area, triangle});
    return;
  }
  // Rotate so that the longest edge is a-b, then split it at its midpoint.
  if (longest == ab) {
    const Eigen::Vector3d m = 0.5 * (a + b);
    splitIntoCells(a, m, c, triangle, max_area, max_edge_sq, cells);
    splitIntoCells(m, b, c, triangle, max_area, max_edge_sq, cells);
  } else if (longest == bc) {
    const Eigen::Vector3d m = 0.5 * (b + c);
    splitIntoCells(b, m, a, triangle, max_area, max_edge_sq, cells);
    splitIntoCells(m, c, a, triangle, max_area, max_edge_sq, cells);
  } else {
    const Eigen::Vector3d m = 0.5 * (c + a);
    splitIntoCells(c, m, b, triangle, max_area, max_edge_sq, cells);
    splitIntoCells(m, a, b, triangle, max_area, max_edge_sq, cells);
  }
}

}  // namespace

SurfaceSamples sampleSurface(const TriangleMesh& mesh, double spacing, std::uint32_t seed) {
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw Error("surface sampling spacing must be a positive length in metres, got " +
                std::to_string(spacing));
  }
  if (mesh.triangles.empty()) {
    throw Error("cannot sample the surface of a mesh without triangles");
  }
  checkMesh(mesh);  // throws for invalid indices or non-finite vertices
  const double total_area = mesh.area();
  const double expected = total_area / (spacing * spacing);
  if (expected > kMaxSamples) {
    throw Error("surface sampling spacing " + std::to_string(spacing) + " m is too small for " +
                "a surface of " + std::to_string(total_area) + " m^2 (" + std::to_string(expected) +
                " points)");
  }
  const auto count = static_cast<std::size_t>(std::llround(expected));

  std::vector<Cell> cells;
  cells.reserve(static_cast<std::size_t>(expected * 1.5) + mesh.triangles.size());
  const double max_edge_sq = 4.0 * spacing * spacing;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    splitIntoCells(mesh.vertices[tri[0]].cast<double>(), mesh.vertices[tri[1]].cast<double>(),
                   mesh.vertices[tri[2]].cast<double>(), static_cast<int>(t), spacing * spacing,
                   max_edge_sq, &cells);
  }
  std::vector<double> cumulative(cells.size());
  double running = 0.0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    running += cells[i].area;
    cumulative[i] = running;
  }

  SurfaceSamples samples;
  samples.points.reserve(count);
  samples.normals.reserve(count);
  if (cells.empty()) return samples;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (std::size_t k = 0; k < count; ++k) {
    const double target = (static_cast<double>(k) + uniform(rng)) / count * running;
    auto it = std::upper_bound(cumulative.begin(), cumulative.end(), target);
    if (it == cumulative.end()) --it;
    const Cell& cell = cells[static_cast<std::size_t>(it - cumulative.begin())];
    // Uniform point in the cell (square-root warp of two uniforms).
    const double s = std::sqrt(uniform(rng));
    const double v = uniform(rng);
    const Eigen::Vector3d p = (1.0 - s) * cell.a + s * (1.0 - v) * cell.b + s * v * cell.c;
    samples.points.push_back(p.cast<float>());
    samples.normals.push_back(mesh.triangleNormal(static_cast<std::size_t>(cell.triangle)));
  }
  return samples;
}

}  // namespace vdc
