#pragma once

#include <map>
#include <vector>

#include "view_direction_classification/bop/bop_depth.h"
#include "view_direction_classification/bop/bop_results.h"
#include "view_direction_classification/bop/bop_types.h"
#include "view_direction_classification/geometry/triangle_mesh.h"

namespace vdc {

// What the scoring needs of one object model: its models_info.json entry, its vertices [mm] and,
// for VSD, its mesh in metres (empty: no VSD).
struct BopScoringModel {
  BopModelInfo info;
  std::vector<Eigen::Vector3d> vertices;
  TriangleMesh mesh_m;
};

// The ground truth of the images scored: their cameras and annotated objects, per scene, and for
// VSD their depth images by (scene_id, im_id) (an image without one: no VSD).
struct BopScoringTruth {
  std::map<int, BopSceneFiles> scenes;
  std::map<std::pair<int, int>, BopDepthImage> depths;
};

// Recall of one object (or of all: obj_id 0) over BOP's thresholds.
struct BopRecall {
  int obj_id = 0;
  int targets = 0;    // instances to find (the targets' inst_count summed)
  int estimates = 0;  // estimates scored (at most inst_count per target, the best-scored)
  double mssd = 0.0;  // average recall over the MSSD thresholds
  double mspd = 0.0;  // average recall over the MSPD thresholds
  // Average recall over VSD's tau and correctness thresholds (bop_vsd.h), when every matched
  // estimate had a mesh and a depth image to be scored with; else vsd_scored is false.
  double vsd = 0.0;
  bool vsd_scored = false;
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
