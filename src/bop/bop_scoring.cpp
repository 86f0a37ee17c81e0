#include "view_direction_classification/bop/bop_scoring.h"

#include <algorithm>
#include <limits>
#include <tuple>

#include "view_direction_classification/bop/bop_metrics.h"
#include "view_direction_classification/bop/bop_vsd.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Errors divided by what scales BOP's thresholds (the diameter; image width / 640), so that all
// objects and images share one list of thresholds and targets can be pooled.
struct NormalisedError {
  double mssd = std::numeric_limits<double>::infinity();
  double mspd = std::numeric_limits<double>::infinity();
  std::vector<double> vsd;  // per tau (vsdTaus of the diameter); empty: not scored
};

using ImageKey = std::tuple<int, int, int>;  // scene_id, im_id, obj_id

std::map<ImageKey, std::vector<const BopEstimate*>> estimatesByTarget(
    const std::vector<BopEstimate>& estimates) {
  std::map<ImageKey, std::vector<const BopEstimate*>> grouped;
  for (const BopEstimate& e : estimates) grouped[{e.scene_id, e.im_id, e.obj_id}].push_back(&e);
  for (auto& [key, list] : grouped) {
    std::stable_sort(list.begin(), list.end(), [](const BopEstimate* a, const BopEstimate* b) {
      return a->score > b->score;
    });
  }
  return grouped;
}

const BopCamera& cameraOf(const BopScoringTruth& truth, int scene_id, int im_id) {
  const auto scene = truth.scenes.find(scene_id);
  if (scene != truth.scenes.end()) {
    const auto camera = scene->second.cameras.find(im_id);
    if (camera != scene->second.cameras.end()) return camera->second;
  }
  throw Error("BOP scoring: scene " + std::to_string(scene_id) + " image " + std::to_string(im_id) +
              " has no camera");
}

std::vector<BopPose> annotatedPoses(const BopScoringTruth& truth, const BopTarget& target) {
  std::vector<BopPose> poses;
  const auto scene = truth.scenes.find(target.scene_id);
  if (scene == truth.scenes.end()) return poses;
  const auto image = scene->second.ground_truth.find(target.im_id);
  if (image == scene->second.ground_truth.end()) return poses;
  for (const BopGtObject& object : image->second) {
    if (object.obj_id == target.obj_id) poses.push_back(object.camera_from_model);
  }
  return poses;
}

// VSD per tau of a matched estimate; empty without the model's mesh or the image's depth.
std::vector<double> vsdErrors(const BopEstimate& estimate, const BopPose& annotated,
                              const BopTarget& target, const BopScoringTruth& truth,
                              const BopScoringModel& model) {
  const auto depth = truth.depths.find({target.scene_id, target.im_id});
  if (model.mesh_m.empty() || depth == truth.depths.end()) return {};
  const BopCamera& camera = cameraOf(truth, target.scene_id, target.im_id);
  const DepthRenderer renderer(model.mesh_m, camera.intrinsics);
  return visibleSurfaceDiscrepancy(estimate.camera_from_model, annotated, renderer, depth->second,
                                   camera.depth_scale, vsdTaus(model.info.diameter));
}

// The errors of the target's matched estimates (greedy, best score first).
std::vector<NormalisedError> targetErrors(const BopTarget& target,
                                          const std::vector<const BopEstimate*>& estimates,
                                          const BopScoringTruth& truth,
                                          const BopScoringModel& model) {
  const std::vector<BopPose> annotated = annotatedPoses(truth, target);
  const CameraIntrinsics& camera = cameraOf(truth, target.scene_id, target.im_id).intrinsics;
  const std::vector<BopPose> symmetries = bopSymmetryTransformations(model.info);
  std::vector<bool> matched(annotated.size(), false);
  std::vector<NormalisedError> errors;
  const std::size_t count = std::min<std::size_t>(estimates.size(), target.inst_count);
  for (std::size_t e = 0; e < count; ++e) {
    int best = -1;
    NormalisedError best_error;
    for (std::size_t g = 0; g < annotated.size(); ++g) {
      if (matched[g]) continue;
      const BopPose& pose = estimates[e]->camera_from_model;
      NormalisedError error;
      error.mssd =
          maximumSymmetryAwareSurfaceDistance(pose, annotated[g], model.vertices, symmetries) /
          model.info.diameter;
      error.mspd = maximumSymmetryAwareProjectionDistance(pose, annotated[g], model.vertices,
                                                          symmetries, camera) *
                   640.0 / camera.width;
      if (best < 0 || error.mssd < best_error.mssd) best = static_cast<int>(g), best_error = error;
    }
    if (best < 0) break;
    matched[best] = true;
    best_error.vsd = vsdErrors(*estimates[e], annotated[best], target, truth, model);
    errors.push_back(best_error);
  }
  return errors;
}

// The mean over VSD's taus and correctness thresholds of the fraction of the targets whose error
// at that tau is below the threshold; scored only if every error has its VSD.
void addVsdRecall(const std::vector<NormalisedError>& errors, BopRecall* recall) {
  recall->vsd_scored = recall->targets > 0;
  for (const NormalisedError& e : errors) recall->vsd_scored &= !e.vsd.empty();
  if (!recall->vsd_scored) return;
  const std::vector<double> thresholds = vsdCorrectThresholds();
  const std::size_t taus = vsdTaus(1.0).size();
  double sum = 0.0;
  for (std::size_t t = 0; t < taus; ++t) {
    for (const double threshold : thresholds) {
      int correct = 0;
      for (const NormalisedError& e : errors) correct += e.vsd[t] < threshold ? 1 : 0;
      sum += std::min(1.0, static_cast<double>(correct) / recall->targets);
    }
  }
  recall->vsd = sum / static_cast<double>(taus * thresholds.size());
}

BopRecall recallOf(int obj_id, int targets, const std::vector<NormalisedError>& errors) {
  std::vector<double> mssd, mspd;
  for (const NormalisedError& e : errors) mssd.push_back(e.mssd), mspd.push_back(e.mspd);
  BopRecall recall;
  recall.obj_id = obj_id;
  recall.targets = targets;
  recall.estimates = static_cast<int>(errors.size());
  recall.mssd = averageRecall(mssd, targets, mssdThresholds(1.0));
  recall.mspd = averageRecall(mspd, targets, mspdThresholds(640));
  addVsdRecall(errors, &recall);
  return recall;
}

}  // namespace

BopScores scoreBopEstimates(const std::vector<BopEstimate>& estimates,
                            const std::vector<BopTarget>& targets, const BopScoringTruth& truth,
                            const std::map<int, BopScoringModel>& models) {
  const auto grouped = estimatesByTarget(estimates);
  std::map<int, std::vector<NormalisedError>> errors_by_object;
  std::map<int, int> targets_by_object;
  for (const BopTarget& target : targets) {
    targets_by_object[target.obj_id] += target.inst_count;
    errors_by_object[target.obj_id];  // an object without estimates still gets its row
    const auto found = grouped.find({target.scene_id, target.im_id, target.obj_id});
    const auto model = models.find(target.obj_id);
    if (found == grouped.end() || model == models.end()) continue;
    const auto errors = targetErrors(target, found->second, truth, model->second);
    errors_by_object[target.obj_id].insert(errors_by_object[target.obj_id].end(), errors.begin(),
                                           errors.end());
  }
  BopScores scores;
  std::vector<NormalisedError> all_errors;
  int all_targets = 0;
  for (const auto& [obj_id, errors] : errors_by_object) {
    scores.per_object.push_back(recallOf(obj_id, targets_by_object[obj_id], errors));
    all_errors.insert(all_errors.end(), errors.begin(), errors.end());
    all_targets += targets_by_object[obj_id];
  }
  scores.overall = recallOf(0, all_targets, all_errors);
  return scores;
}

}  // namespace vdc
