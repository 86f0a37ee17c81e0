#include "view_direction_classification/geometry/visibility_crop.h"

#include <cmath>
#include <limits>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void checkCropArguments(const std::vector<Eigen::Vector3d>& anchors, double radius) {
  if (anchors.empty()) {
    throw Error("the visibility crop needs at least one anchor point");
  }
  for (const auto& anchor : anchors) {
    if (!anchor.allFinite()) throw Error("a visibility crop anchor point is not finite");
  }
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw Error("the visibility crop radius must be positive and finite, got " +
                std::to_string(radius) + " m");
  }
}

bool nearAnyAnchor(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& anchors,
                   double radius_sq) {
  for (const auto& anchor : anchors) {
    if ((p - anchor).squaredNorm() <= radius_sq) return true;
  }
  return false;
}

}  // namespace

pcl::PointCloud<pcl::PointXYZ> cropToAnchors(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud,
                                             const Eigen::Isometry3d& camera_from_object,
                                             const std::vector<Eigen::Vector3d>& anchors,
                                             double radius) {
  checkCropArguments(anchors, radius);
  std::vector<Eigen::Vector3d> camera_anchors;
  camera_anchors.reserve(anchors.size());
  for (const auto& anchor : anchors) camera_anchors.push_back(camera_from_object * anchor);

  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> cropped = camera_cloud;
  const double radius_sq = radius * radius;
  for (auto& p : cropped.points) {
    const Eigen::Vector3d point(p.x, p.y, p.z);
    if (!point.allFinite() || !nearAnyAnchor(point, camera_anchors, radius_sq)) {
      p.x = p.y = p.z = nan;
    }
  }
  cropped.is_dense = false;
  return cropped;
}

double surfaceFractionNearAnchors(const SurfaceSamples& surface,
                                  const std::vector<Eigen::Vector3d>& anchors, double radius) {
  checkCropArguments(anchors, radius);
  if (surface.size() == 0) {
    throw Error("cannot compute the visible surface fraction of an empty surface set");
  }
  const double radius_sq = radius * radius;
  std::size_t near = 0;
  for (const auto& p : surface.points) {
    if (nearAnyAnchor(p.cast<double>(), anchors, radius_sq)) ++near;
  }
  return static_cast<double>(near) / static_cast<double>(surface.size());
}

}  // namespace vdc
