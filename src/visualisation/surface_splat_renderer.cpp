#include "view_direction_classification/visualisation/surface_splat_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {

RgbImage renderSplats(const std::vector<Eigen::Vector3f>& points,
                      const std::vector<Eigen::Vector3f>& normals, const std::vector<Rgb>& colours,
                      const SplatView& view) {
  if (points.size() != normals.size() || points.size() != colours.size()) {
    throw Error("renderSplats: points, normals and colours differ in number");
  }
  if (!(view.direction.norm() > 0.0) || !view.direction.allFinite()) {
    throw Error("renderSplats: the viewing direction must be a non-zero vector");
  }
  RgbImage image(view.size, view.size, view.background);
  if (points.empty()) return image;

  const Eigen::Vector3d toward_viewer = view.direction.normalized();
  // Object +z is drawn upwards unless the view looks along it.
  const Eigen::Vector3d up_hint =
      std::abs(toward_viewer.z()) > 0.99 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d right = up_hint.cross(toward_viewer).normalized();
  const Eigen::Vector3d up = toward_viewer.cross(right);

  // The same scale from every direction (the bounding sphere about the centroid), so pictures of
  // one object from several views compare.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p.cast<double>();
  centroid /= static_cast<double>(points.size());
  double radius = 0.0;
  for (const auto& p : points) radius = std::max(radius, (p.cast<double>() - centroid).norm());
  radius = std::max(radius, 1e-6);
  const double scale = 0.45 * view.size / radius;  // pixels per metre, 10 % margin
  const double half = 0.5 * view.size;
  // Stratified samples leave gaps of up to ~1.5 spacings; discs of one spacing radius close them
  // without blurring the 5 mm score neighbourhoods.
  const double disc = std::max(1.5, 1.0 * view.point_spacing * scale);
  const int reach = static_cast<int>(std::ceil(disc));

  std::vector<double> depth(static_cast<std::size_t>(view.size) * view.size,
                            -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (normals[i].cast<double>().dot(toward_viewer) <= 0.0) continue;  // faces away
    const Eigen::Vector3d p = points[i].cast<double>() - centroid;
    const double u = half + scale * p.dot(right);
    const double v = half - scale * p.dot(up);
    const double z = p.dot(toward_viewer);  // larger is nearer the viewer
    const int cx = static_cast<int>(std::lround(u));
    const int cy = static_cast<int>(std::lround(v));
    for (int y = std::max(0, cy - reach); y <= std::min(view.size - 1, cy + reach); ++y) {
      for (int x = std::max(0, cx - reach); x <= std::min(view.size - 1, cx + reach); ++x) {
        if ((x - u) * (x - u) + (y - v) * (y - v) > disc * disc) continue;
        double& d = depth[static_cast<std::size_t>(y) * view.size + x];
        if (z > d) {
          d = z;
          image.set(x, y, colours[i]);
        }
      }
    }
  }
  return image;
}

}  // namespace vdc
