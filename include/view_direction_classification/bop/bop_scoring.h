#pragma once

#include <map>
#include <vector>

#include "view_direction_classification/bop/bop_results.h"
#include "view_direction_classification/bop/bop_types.h"

namespace vdc {

// What the scoring needs of one object model: its models_info.json entry and its vertices [mm].
struct BopScoringModel {
  BopModelInfo info;
  std::vector<Eigen::Vector3d> vertices;
};

// The ground truth of the images scored: their cameras and annotated objects, per scene.
struct BopScoringTruth {
  std::map<int, BopSceneFiles> scenes;
};

// Recall of one object (or of all: obj_id 0) over BOP's thresholds.
struct BopRecall {
  int obj_id = 0;
  int targets = 0;    // instances to find (the targets' inst_count summed)
  int estimates = 0;  // estimates scored (at most inst_count per target, the best-scored)
  double mssd = 0.0;  // average recall over the MSSD thresholds
  double mspd = 0.0;  // average recall over the MSPD thresholds
};

struct BopScores {
  std::vector<BopRecall> per_object;  // ascending obj_id
  BopRecall overall;                  // all targets pooled, each with its own object's thresholds
};

// Scores estimates as BOP's 2019 protocol does with MSSD and MSPD (bop_toolkit's
// eval_calc_errors / eval_calc_scores, simplified): per target (scene, image, object), the
// inst_count best-scored estimates are each matched, best score first, to the not yet matched
// annotated instance of the object with the smallest error; an error at most the threshold is a
// correct pose. Unlike BOP, one matching serves all thresholds (the same when an image holds one
// instance of the object), and instances are not filtered by visibility (no scene_gt_info.json):
// the targets decide what is to be found. A target whose object has no model entry or no truth
// counts its instances as missed. Throws vdc::Error for an estimate's image without a camera.
BopScores scoreBopEstimates(const std::vector<BopEstimate>& estimates,
                            const std::vector<BopTarget>& targets, const BopScoringTruth& truth,
                            const std::map<int, BopScoringModel>& models);

}  // namespace vdc
