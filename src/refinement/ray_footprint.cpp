#include "ray_footprint.h"

#include <algorithm>

namespace vdc {

namespace {

// > 0 when o -> a -> b turns counter-clockwise.
float cross(const Eigen::Vector2f& o, const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

std::vector<Eigen::Vector2f> convexHull(std::vector<Eigen::Vector2f> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return {};
  std::vector<Eigen::Vector2f> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2f& p : points) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0f) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], *it) <= 0.0f) --k;
    hull[k++] = *it;
  }
  hull.resize(k - 1);  // the last point is the first again
  if (hull.size() < 3) hull.clear();
  return hull;
}

bool insideConvexPolygon(const std::vector<Eigen::Vector2f>& polygon, const Eigen::Vector2f& p,
                         float tolerance) {
  if (polygon.size() < 3) return false;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2f& a = polygon[i];
    const Eigen::Vector2f& b = polygon[(i + 1) % polygon.size()];
    const float length = (b - a).norm();
    // The signed distance of p to the edge's line, positive inside.
    if (cross(a, b, p) < -tolerance * length) return false;
  }
  return true;
}

}  // namespace vdc
