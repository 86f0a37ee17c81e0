// OrientationEstimator::snapshot and restore: what a restart carries over (estimator_snapshot.h).
// Kept apart from orientation_estimator.cpp, whose subject is the update.
#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/estimation/orientation_estimator.h"

namespace vdc {
namespace {

template <typename Derived>
void checkFinite(const std::optional<Derived>& value, const char* name) {
  if (value && !value->allFinite())
    throw Error(std::string("the snapshot's ") + name + " is not finite");
}

// Everything restore() relies on, checked before anything is changed.
void checkSnapshot(const EstimatorSnapshot& s) {
  if (s.update_count < 0) {
    throw Error("the snapshot's update count must be >= 0, got " + std::to_string(s.update_count));
  }
  for (const Eigen::Vector3d& view : s.fused_views) {
    // FusedViews::add normalises, so any finite non-zero direction would do; a saved one is
    // unit, and one far from it means a damaged value rather than a rounding.
    if (!view.allFinite() || std::abs(view.norm() - 1.0) > 1e-6) {
      throw Error("a fused view of the snapshot is not a unit direction");
    }
  }
  if (s.track) {
    if (!s.track->centroid.allFinite()) throw Error("the snapshot's track centroid is not finite");
    checkFinite(s.track->table, "track table");
  }
  checkFinite(s.last_centroid_world, "last centroid");
  checkFinite(s.last_camera_position_world, "last camera position");
  checkFinite(s.refined_position, "refined position");
  checkFinite(s.refined_position_covariance, "position covariance");
  if (s.refined_position_covariance &&
      !s.refined_position_covariance->isApprox(s.refined_position_covariance->transpose())) {
    throw Error("the snapshot's position covariance is not symmetric");
  }
  if (s.confirmed_fit_score && !std::isfinite(*s.confirmed_fit_score)) {
    throw Error("the snapshot's confirmed fit score is not finite");
  }
}

}  // namespace

EstimatorSnapshot OrientationEstimator::snapshot() const {
  EstimatorSnapshot s;
  s.belief = filter_.belief();
  s.update_count = filter_.updateCount();
  s.fused_views = fused_views_.directions();
  s.track = track_;
  s.last_centroid_world = last_centroid_world_;
  s.last_camera_position_world = last_camera_position_world_;
  s.refined_position = refined_position_;
  s.refined_position_covariance = refined_position_covariance_;
  s.confirmed_fit_score = confirmed_fit_score_;
  return s;
}

void OrientationEstimator::restore(const EstimatorSnapshot& snapshot) {
  checkSnapshot(snapshot);
  FusedViews views;
  for (const Eigen::Vector3d& view : snapshot.fused_views) views.add(view);
  reset();  // clears the caches, the latest views and the rest restored below
  last_pose_.reset();
  filter_.restore(snapshot.belief, snapshot.update_count);
  fused_views_ = std::move(views);
  track_ = snapshot.track;
  last_centroid_world_ = snapshot.last_centroid_world;
  last_camera_position_world_ = snapshot.last_camera_position_world;
  refined_position_ = snapshot.refined_position;
  refined_position_covariance_ = snapshot.refined_position_covariance;
  confirmed_fit_score_ = snapshot.confirmed_fit_score;
}

}  // namespace vdc
