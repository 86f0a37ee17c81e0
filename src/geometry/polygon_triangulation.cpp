#include "polygon_triangulation.h"

#include <Eigen/Geometry>

#include <cmath>

namespace vdc {
namespace {

using Point = Eigen::Vector2d;

double cross(const Point& a, const Point& b, const Point& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// The corners in the plane through the polygon (Newell's normal), counter-clockwise; empty if
// the polygon has no area to fix a plane by.
std::vector<Point> projectCounterClockwise(const std::vector<Eigen::Vector3f>& vertices,
                                           const std::int32_t* corners, std::size_t count) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d a = vertices[corners[i]].cast<double>();
    const Eigen::Vector3d b = vertices[corners[(i + 1) % count]].cast<double>();
    normal += Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                              (a.x() - b.x()) * (a.y() + b.y()));
  }
  if (!(normal.norm() > 0.0)) return {};
  normal.normalize();
  // Any right-handed basis (u, v, normal) puts the polygon counter-clockwise.
  const Eigen::Vector3d u = normal.unitOrthogonal();
  const Eigen::Vector3d v = normal.cross(u);
  std::vector<Point> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d p = vertices[corners[i]].cast<double>();
    points.emplace_back(p.dot(u), p.dot(v));
  }
  return points;
}

bool isConvex(const std::vector<Point>& points) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (cross(points[(i + n - 1) % n], points[i], points[(i + 1) % n]) < 0.0) return false;
  }
  return true;
}

bool inTriangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
}

// Ear clipping on a ring of corner positions: a corner is an ear if it is convex and no concave
// corner lies in the triangle it makes with its neighbours (only concave corners can).
class EarClipper {
 public:
  explicit EarClipper(const std::vector<Point>& points)
      : points_(points), previous_(points.size()), next_(points.size()) {
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i) {
      previous_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
    }
    // Enough for every ear search of a simple polygon; past it the rest is cut as a fan.
    budget_ = 8 * n * n;
  }

  // Triangles as positions in the ring, wound as the ring.
  std::vector<Eigen::Vector3i> clip() {
    std::vector<Eigen::Vector3i> ears;
    std::size_t remaining = points_.size(), corner = 0, misses = 0;
    while (remaining > 3) {
      // After a whole round without an ear the ring is no simple polygon: cut where we are.
      if (misses < remaining && !isEar(corner)) {
        corner = next_[corner];
        ++misses;
        continue;
      }
      ears.emplace_back(previous_[corner], corner, next_[corner]);
      next_[previous_[corner]] = next_[corner];
      previous_[next_[corner]] = previous_[corner];
      corner = previous_[corner];
      --remaining;
      misses = 0;
    }
    ears.emplace_back(previous_[corner], corner, next_[corner]);
    return ears;
  }

 private:
  bool isConcave(std::size_t i) const {
    return cross(points_[previous_[i]], points_[i], points_[next_[i]]) < 0.0;
  }

  bool isEar(std::size_t i) {
    const std::size_t a = previous_[i], c = next_[i];
    if (cross(points_[a], points_[i], points_[c]) <= 0.0) return false;
    if (budget_ == 0) return true;
    for (std::size_t j = next_[c]; j != a; j = next_[j]) {
      if (budget_ > 0) --budget_;
      if (isConcave(j) && inTriangle(points_[j], points_[a], points_[i], points_[c])) return false;
    }
    return true;
  }

  const std::vector<Point>& points_;
  std::vector<std::size_t> previous_, next_;
  std::size_t budget_ = 0;
};

}  // namespace

void triangulatePolygon(const std::vector<Eigen::Vector3f>& vertices, const std::int32_t* corners,
                        std::size_t count, std::vector<Eigen::Vector3i>* triangles) {
  const std::vector<Point> points = projectCounterClockwise(vertices, corners, count);
  if (count == 3 || points.empty() || isConvex(points)) {
    for (std::size_t i = 1; i + 1 < count; ++i) {
      triangles->emplace_back(corners[0], corners[i], corners[i + 1]);
    }
    return;
  }
  for (const Eigen::Vector3i& ear : EarClipper(points).clip()) {
    triangles->emplace_back(corners[ear[0]], corners[ear[1]], corners[ear[2]]);
  }
}

}  // namespace vdc
