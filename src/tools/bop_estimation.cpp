#include "bop_estimation.h"

#include <algorithm>
#include <chrono>

#include "view_direction_classification/bop/bop_units.h"
#include "view_direction_classification/recognition/instance_overlap.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc::tools {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The estimator's confirmed instances of each target's object, most probable first.
std::vector<BopEstimate> estimatesOf(const SceneEstimator& estimator,
                                     const std::vector<BopTarget>& targets,
                                     const Eigen::Isometry3d& world_from_camera, double time_s) {
  std::vector<BopEstimate> estimates;
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  for (const BopTarget& target : targets) {
    const int model = estimator.library().find(std::to_string(target.obj_id));
    if (model < 0) continue;
    std::vector<const ObjectInstance*> found;
    for (const ObjectInstance& instance : estimator.instances()) {
      if (instance.model == model && estimator.confirmed(instance) &&
          instance.estimator->positionEstimate()) {
        found.push_back(&instance);
      }
    }
    std::stable_sort(found.begin(), found.end(), [](const auto* a, const auto* b) {
      return a->identity_probability > b->identity_probability;
    });
    found.resize(std::min<std::size_t>(found.size(), target.inst_count));
    for (const ObjectInstance* instance : found) {
      BopEstimate estimate;
      estimate.scene_id = target.scene_id;
      estimate.im_id = target.im_id;
      estimate.obj_id = target.obj_id;
      estimate.score = instance->identity_probability;
      estimate.camera_from_model =
          bopPoseOf(camera_from_world * *believedPose(*instance->estimator));
      estimate.time_s = time_s;
      estimates.push_back(estimate);
    }
  }
  return estimates;
}

pcl::PointCloud<pcl::PointXYZ> imageCloud(const BopEstimationInput& input, int im_id) {
  return bopDepthCloud(input.dataset->depth(input.scene_id, im_id), input.files.cameras.at(im_id));
}

void append(BopEstimation* all, const std::vector<BopEstimate>& more, double seconds) {
  all->estimates.insert(all->estimates.end(), more.begin(), more.end());
  all->image_seconds.push_back(seconds);
}

}  // namespace

ModelLibrary bopModelLibrary(const std::map<int, std::string>& bundle_paths) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& [obj_id, path] : bundle_paths)
    entries.emplace_back(std::to_string(obj_id), path);
  return ModelLibrary::load(entries);
}

BopEstimation estimateSingleViews(const BopEstimationInput& input, const ModelLibrary& library,
                                  const SceneEstimatorParameters& parameters) {
  BopEstimation estimates;
  for (const auto& [im_id, targets] : input.targets_by_image) {
    if (input.files.cameras.count(im_id) == 0) continue;  // scored as missed
    const auto cloud = imageCloud(input, im_id);
    const auto start = std::chrono::steady_clock::now();
    SceneEstimator estimator(library, parameters);
    estimator.update(cloud, Eigen::Isometry3d::Identity(), 0.0);
    const double seconds = secondsSince(start);
    append(&estimates, estimatesOf(estimator, targets, Eigen::Isometry3d::Identity(), seconds),
           seconds);
  }
  return estimates;
}

BopEstimation estimateViewSequence(const BopEstimationInput& input, const ModelLibrary& library,
                                   const SceneEstimatorParameters& parameters) {
  for (const auto& [im_id, camera] : input.files.cameras) {
    if (!camera.camera_from_world) return {};
  }
  BopEstimation estimates;
  SceneEstimator estimator(library, parameters);
  for (const auto& [im_id, camera] : input.files.cameras) {
    const Eigen::Isometry3d world_from_camera = isometryOf(*camera.camera_from_world).inverse();
    const auto cloud = imageCloud(input, im_id);
    const auto start = std::chrono::steady_clock::now();
    estimator.update(cloud, world_from_camera, static_cast<double>(im_id));
    const double seconds = secondsSince(start);
    const auto targets = input.targets_by_image.find(im_id);
    if (targets == input.targets_by_image.end()) continue;
    append(&estimates, estimatesOf(estimator, targets->second, world_from_camera, seconds),
           seconds);
  }
  return estimates;
}

}  // namespace vdc::tools
