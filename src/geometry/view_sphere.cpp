#include "view_direction_classification/geometry/view_sphere.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr int kMaxDirections = 10000;

// Fibonacci lattice: equal-area latitude bands, longitudes advancing by the golden angle.
std::vector<Eigen::Vector3d> fibonacciLattice(int count) {
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<Eigen::Vector3d> v;
  v.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double lon = golden_angle * i;
    v.emplace_back(r * std::cos(lon), r * std::sin(lon), z);
  }
  return v;
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Radius of a cap around direction m containing its Voronoi cell: the largest angle to a cell
// vertex. Cell vertices are points equidistant from m and two others (j, k) and no nearer to any
// fourth direction. On a near-uniform set the cell's neighbours are among the few nearest
// directions, so only those pairs are tried. A direction nearer to a candidate vertex c than m is
// within twice the angle (m, c) of m, so the vertex test needs only the candidates when the
// farthest candidate is beyond that, and falls back to all directions otherwise.
double voronoiCellRadius(const std::vector<Eigen::Vector3d>& d, int m) {
  const int count = static_cast<int>(d.size());
  // With fewer than 4 directions a cell can exceed a hemisphere and is no longer a convex
  // polygon: bound it by the whole sphere.
  if (count < 4) return M_PI;
  std::vector<int> others(count - 1);
  std::iota(others.begin(), others.begin() + m, 0);
  std::iota(others.begin() + m, others.end(), m + 1);
  const int candidates = std::min<int>(count - 1, 16);
  std::partial_sort(others.begin(), others.begin() + candidates, others.end(),
                    [&](int a, int b) { return d[a].dot(d[m]) > d[b].dot(d[m]); });
  double radius = 0.0;
  int vertices = 0;
  for (int a = 0; a < candidates; ++a) {
    for (int b = a + 1; b < candidates; ++b) {
      const int j = others[a], k = others[b];
      Eigen::Vector3d c = (d[j] - d[m]).cross(d[k] - d[m]);
      if (c.norm() < 1e-12) continue;
      c.normalize();
      if (c.dot(d[m]) < 0.0) c = -c;
      const double own = c.dot(d[m]);
      const double to_vertex = angleBetween(c, d[m]);
      const bool candidates_suffice =
          2.0 * to_vertex < angleBetween(d[others[candidates - 1]], d[m]);
      const int tested = candidates_suffice ? candidates : count - 1;
      bool is_vertex = true;
      for (int i = 0; i < tested && is_vertex; ++i) {
        const int q = others[i];
        if (q != j && q != k && c.dot(d[q]) > own + 1e-12) is_vertex = false;
      }
      if (!is_vertex) continue;
      ++vertices;
      radius = std::max(radius, to_vertex);
    }
  }
  if (vertices < 3) return M_PI;
  // A hair of margin against rounding: the cap only has to contain the cell.
  return std::min(M_PI, radius * (1.0 + 1e-9) + 1e-12);
}

}  // namespace

Icosphere makeIcosphere(int level) {
  if (level < 0 || level > 6) {
    throw Error("icosphere subdivision level must be in [0, 6], got " + std::to_string(level));
  }
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  Icosphere sphere;
  sphere.vertices = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                     {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                     {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (auto& p : sphere.vertices) p.normalize();
  sphere.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                  {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                  {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                  {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  std::vector<Eigen::Vector3d>& v = sphere.vertices;
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      v.push_back((v[a] + v[b]).normalized());
      const int index = static_cast<int>(v.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Eigen::Vector3i> finer;
    finer.reserve(sphere.faces.size() * 4);
    for (const auto& f : sphere.faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.emplace_back(f[0], ab, ca);
      finer.emplace_back(f[1], bc, ab);
      finer.emplace_back(f[2], ca, bc);
      finer.emplace_back(ab, bc, ca);
    }
    sphere.faces = std::move(finer);
  }
  return sphere;
}

ViewSphere::ViewSphere(int count) {
  if (count < 2 || count > kMaxDirections) {
    throw Error("the number of viewing directions must be between 2 and " +
                std::to_string(kMaxDirections) + ", got " + std::to_string(count));
  }
  switch (count) {
    case 12:
      directions_ = makeIcosphere(0).vertices;
      break;
    case 42:
      directions_ = makeIcosphere(1).vertices;
      break;
    case 162:
      directions_ = makeIcosphere(2).vertices;
      break;
    case 642:
      directions_ = makeIcosphere(3).vertices;
      break;
    default:
      directions_ = fibonacciLattice(count);
  }
  cell_radius_.resize(directions_.size());
  double angle_sum = 0.0;
  for (int m = 0; m < size(); ++m) {
    double closest = M_PI;
    for (int j = 0; j < size(); ++j) {
      if (j != m) closest = std::min(closest, angleBetween(directions_[m], directions_[j]));
    }
    angle_sum += closest;
    cell_radius_[m] = voronoiCellRadius(directions_, m);
  }
  neighbour_angle_ = angle_sum / size();
}

void ViewSphere::checkIndex(int m) const {
  if (m < 0 || m >= size()) {
    throw Error("viewing direction index " + std::to_string(m) + " is out of range [0, " +
                std::to_string(size()) + ")");
  }
}

const Eigen::Vector3d& ViewSphere::direction(int m) const {
  checkIndex(m);
  return directions_[m];
}

double ViewSphere::cellRadius(int m) const {
  checkIndex(m);
  return cell_radius_[m];
}

int ViewSphere::nearest(const Eigen::Vector3d& direction) const {
  const double length = direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw Error("cannot find the viewing-direction cell of a zero or non-finite vector");
  }
  int best = 0;
  double best_dot = -2.0;
  for (int m = 0; m < size(); ++m) {
    const double dot = directions_[m].dot(direction);
    if (dot > best_dot) {
      best_dot = dot;
      best = m;
    }
  }
  return best;
}

Eigen::Vector3d ViewSphere::sampleInCell(int m, std::mt19937& rng) const {
  checkIndex(m);
  const Eigen::Vector3d& axis = directions_[m];
  // Orthonormal basis (e1, e2, axis).
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = axis.cross(helper).normalized();
  const Eigen::Vector3d e2 = axis.cross(e1);
  const double min_cos = std::cos(cell_radius_[m]);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Uniform on the cap (Archimedes: uniform in height), kept if it falls in the cell. The cap is
  // at most a few times the cell's area, so this ends after a handful of draws.
  while (true) {
    const double z = 1.0 - uniform(rng) * (1.0 - min_cos);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double lon = 2.0 * M_PI * uniform(rng);
    const Eigen::Vector3d candidate =
        (z * axis + r * std::cos(lon) * e1 + r * std::sin(lon) * e2).normalized();
    if (nearest(candidate) == m) return candidate;
  }
}

}  // namespace vdc
