#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "view_direction_classification/bop/bop_dataset.h"
#include "view_direction_classification/bop/bop_results.h"
#include "view_direction_classification/recognition/scene_estimator.h"

namespace vdc::tools {

// `vdc evaluate-bop`'s estimation: the scene estimator (recognition/scene_estimator.h, the
// node's defaults) on a BOP scene's depth images, with a library of one trained bundle per
// obj_id. For each target (an object and its instance count in an image), the confirmed
// instances of that object, most probable first, inst_count of them at most, become estimates
// with their identity probability as score and the image's update time as time.
struct BopEstimationInput {
  const BopDatasetReader* dataset = nullptr;
  int scene_id = 0;
  BopSceneFiles files;
  std::map<int, std::vector<BopTarget>> targets_by_image;  // the scene's, by im_id
};

// The estimates of some images and the estimator's time on each image [s].
struct BopEstimation {
  std::vector<BopEstimate> estimates;
  std::vector<double> image_seconds;
};

// The library's model names are the obj_ids' decimal text.
ModelLibrary bopModelLibrary(const std::map<int, std::string>& bundle_paths);

// Each image alone, from its depth only: a fresh estimator per image, camera at the origin of
// its own fixed frame (no camera pose used).
BopEstimation estimateSingleViews(const BopEstimationInput& input, const ModelLibrary& library,
                                  const SceneEstimatorParameters& parameters);

// The scene's images as one view sequence (ascending im_id) into one estimator, placed with the
// scene's camera poses (cam_R_w2c, cam_t_w2c); each image's estimates are what the estimator
// holds after fusing it and the images before; every image of the scene is fused, the targets'
// and the others. Empty if an image of the scene has no camera pose.
BopEstimation estimateViewSequence(const BopEstimationInput& input, const ModelLibrary& library,
                                   const SceneEstimatorParameters& parameters);

}  // namespace vdc::tools
