#include "view_direction_classification/evaluation/table_footprint.h"

#include <algorithm>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// Andrew's monotone chain: the convex hull, counter-clockwise, collinear points dropped.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2d& p : points) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

// The gap between b and a along the outward normals of a's edges, the largest one.
double largestGapAlongEdgeNormalsOf(const Footprint& a, const Footprint& b) {
  double largest = -std::numeric_limits<double>::infinity();
  const std::size_t n = a.corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = a.corners[(i + 1) % n] - a.corners[i];
    if (edge.norm() == 0.0) continue;
    const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    double a_max = -std::numeric_limits<double>::infinity();
    double b_min = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& p : a.corners) a_max = std::max(a_max, normal.dot(p));
    for (const Eigen::Vector2d& p : b.corners) b_min = std::min(b_min, normal.dot(p));
    largest = std::max(largest, b_min - a_max);
  }
  return largest;
}

}  // namespace

Eigen::Vector2d Footprint::centre() const {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& c : corners) sum += c;
  return corners.empty() ? sum : Eigen::Vector2d(sum / static_cast<double>(corners.size()));
}

Footprint Footprint::shifted(const Eigen::Vector2d& offset) const {
  Footprint result = *this;
  for (Eigen::Vector2d& c : result.corners) c += offset;
  return result;
}

Footprint footprintOf(const TriangleMesh& mesh, const Eigen::Isometry3d& world_from_object) {
  if (mesh.vertices.empty()) throw Error("cannot place an object without vertices on the table");
  std::vector<Eigen::Vector2d> projected;
  projected.reserve(mesh.vertices.size());
  for (const Eigen::Vector3f& v : mesh.vertices) {
    projected.push_back((world_from_object * v.cast<double>()).head<2>());
  }
  return {convexHull(std::move(projected))};
}

double footprintSeparation(const Footprint& a, const Footprint& b) {
  return std::max(largestGapAlongEdgeNormalsOf(a, b), largestGapAlongEdgeNormalsOf(b, a));
}

bool footprintInsideRectangle(const Footprint& footprint, const Eigen::Vector2d& size) {
  const Eigen::Vector2d half = size / 2.0;
  return std::all_of(
      footprint.corners.begin(), footprint.corners.end(),
      [&](const Eigen::Vector2d& c) { return (c.cwiseAbs() - half).maxCoeff() <= 0; });
}

}  // namespace vdc
