#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/estimation/object_tracking.h"

namespace vdc {

// What an OrientationEstimator must carry over a restart to publish the same pose, cone and
// covariance and to go on fusing where it stopped (the scene memory file, scene_memory_file.h).
// Left out on purpose: the camera's last pose (the tf-jump check is about a camera stream, and a
// restart starts a new one), the latest views' points (refinement and the belief check rebuild
// them from the next views) and the caches (the MAP and the spread are recomputed from the
// belief, with the same fixed seed).
struct EstimatorSnapshot {
  BinghamMixture belief;  // q_WO
  int update_count = 0;   // measurements fused (OrientationEstimator::updateCount)
  std::vector<Eigen::Vector3d> fused_views;  // unit directions, fixed frame
  std::optional<ObjectTrack> track;
  // The last observed centroid and the camera position it was seen from (fixed frame): the
  // position estimate without refinement.
  std::optional<Eigen::Vector3d> last_centroid_world, last_camera_position_world;
  std::optional<Eigen::Vector3d> refined_position;
  std::optional<Eigen::Matrix3d> refined_position_covariance;
  std::optional<double> confirmed_fit_score;
};

}  // namespace vdc
