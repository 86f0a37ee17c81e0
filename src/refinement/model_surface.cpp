#include "view_direction_classification/refinement/model_surface.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"

namespace vdc {

ModelSurface::ModelSurface(const std::vector<Eigen::Vector3f>& points,
                           const std::vector<Eigen::Vector3f>& normals,
                           const Eigen::AlignedBox3d& bounds, double source_spacing, double spacing)
    : cloud_(new pcl::PointCloud<pcl::PointNormal>), bounds_(bounds) {
  if (points.size() != normals.size()) {
    throw Error("the model surface has " + std::to_string(points.size()) + " points but " +
                std::to_string(normals.size()) + " normals");
  }
  if (points.size() < 10) {
    throw Error("the model surface needs at least 10 samples to refine against, got " +
                std::to_string(points.size()));
  }
  if (bounds.isEmpty() || !bounds.min().allFinite() || !bounds.max().allFinite()) {
    throw Error("the model surface needs a non-empty, finite extent");
  }
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !(source_spacing > 0.0) ||
      !std::isfinite(source_spacing)) {
    throw Error("the model surface's spacings must be positive and finite, got " +
                std::to_string(source_spacing) + " and " + std::to_string(spacing));
  }
  // The stratified set's k-th samples follow the surface in a spatially coherent order, so
  // keeping every stride-th one thins it evenly.
  const double ratio = spacing / source_spacing;
  const std::size_t stride = std::max<std::size_t>(1, static_cast<std::size_t>(ratio * ratio));
  spacing_ = source_spacing * std::sqrt(static_cast<double>(stride));
  for (std::size_t i = 0; i < points.size(); i += stride) {
    if (!points[i].allFinite() || !normals[i].allFinite()) {
      throw Error("the model surface has a non-finite sample (index " + std::to_string(i) + ")");
    }
    pcl::PointNormal point;
    point.getVector3fMap() = points[i];
    point.getNormalVector3fMap() = normals[i].normalized();
    cloud_->push_back(point);
  }
  tree_.setInputCloud(cloud_);
  std::vector<Eigen::Vector3f> samples;
  samples.reserve(cloud_->size());
  for (const auto& point : cloud_->points) samples.push_back(point.getVector3fMap());
  nearest_ = std::make_unique<const NearestPoints>(std::move(samples));
}

}  // namespace vdc
