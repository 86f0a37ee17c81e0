#include "view_direction_classification/refinement/pose_verification.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

namespace {

void checkNonNegative(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(std::string("refinement's ") + name + " must be >= 0 and finite, got " +
                std::to_string(value));
  }
}

}  // namespace

PoseVerifier::PoseVerifier(std::shared_ptr<const ModelSurface> surface,
                           const std::vector<RefinementView>& views,
                           VerificationParameters parameters)
    : surface_(std::move(surface)), parameters_(parameters) {
  checkNonNegative(parameters_.inlier_distance, "inlier_distance");
  checkNonNegative(parameters_.free_space_tolerance, "free_space_tolerance");
  checkNonNegative(parameters_.min_facing_cosine, "min_facing_cosine");
  neighbour_radius_ = std::max(0.004, 2.0 * surface_->spacing());
  for (const RefinementView& view : views) {
    if (!view.points || view.points->empty()) continue;
    auto indexed = std::make_unique<IndexedView>();
    indexed->points = view.points;
    indexed->rays.reset(new pcl::PointCloud<pcl::PointXYZ>);
    indexed->rays->reserve(view.points->size());
    for (const auto& p : view.points->points) {
      indexed->rays->push_back(pcl::PointXYZ(p.x / p.z, p.y / p.z, 0.0f));
    }
    indexed->ray_tree.setInputCloud(indexed->rays);
    indexed->camera_from_world = view.world_from_camera.inverse();
    views_.push_back(std::move(indexed));
  }
}

VerificationScore PoseVerifier::score(const Eigen::Isometry3d& world_from_object) const {
  VerificationScore result;
  int inliers = 0, violations = 0;
  for (const auto& view : views_) {
    addViewScore(*view, world_from_object, &inliers, &violations, &result);
  }
  if (result.observed > 0) result.inlier_fraction = double(inliers) / result.observed;
  if (result.predicted > 0) result.violation_fraction = double(violations) / result.predicted;
  return result;
}

void PoseVerifier::addViewScore(const IndexedView& view, const Eigen::Isometry3d& world_from_object,
                                int* inliers, int* violations, VerificationScore* score) const {
  const Eigen::Isometry3d camera_from_object = view.camera_from_world * world_from_object;
  const Eigen::Isometry3f object_from_camera = camera_from_object.inverse().cast<float>();
  std::vector<int> index(1);
  std::vector<float> squared(1);
  const float radius_sq = static_cast<float>(neighbour_radius_ * neighbour_radius_);

  // The observed half: is each point on the model's surface?
  const auto& model = *surface_->cloud();
  for (const auto& p : view.points->points) {
    pcl::PointNormal query;
    query.getVector3fMap() = object_from_camera * p.getVector3fMap();
    ++score->observed;
    if (surface_->tree().nearestKSearch(query, 1, index, squared) < 1) continue;
    if (squared[0] > radius_sq) continue;
    const auto& sample = model[index[0]];
    const float offset =
        sample.getNormalVector3fMap().dot(query.getVector3fMap() - sample.getVector3fMap());
    if (std::abs(offset) <= parameters_.inlier_distance) ++*inliers;
  }

  // The predicted half: is each camera-facing sample where the camera saw a surface?
  const Eigen::Isometry3f transform = camera_from_object.cast<float>();
  const Eigen::Matrix3f rotation = transform.linear();
  for (const auto& sample : model.points) {
    const Eigen::Vector3f m = transform * sample.getVector3fMap();
    if (!(m.z() > 0.0f)) continue;
    const Eigen::Vector3f n = rotation * sample.getNormalVector3fMap();
    if (-n.dot(m) / m.norm() < parameters_.min_facing_cosine) continue;
    ++score->predicted;
    const pcl::PointXYZ ray(m.x() / m.z(), m.y() / m.z(), 0.0f);
    const float ray_radius = static_cast<float>(neighbour_radius_) / m.z();
    if (view.ray_tree.nearestKSearch(ray, 1, index, squared) < 1 ||
        squared[0] > ray_radius * ray_radius) {
      ++*violations;  // predicted where nothing was seen
      continue;
    }
    if (m.z() < (*view.points)[index[0]].z - parameters_.free_space_tolerance) ++*violations;
  }
}

}  // namespace vdc
